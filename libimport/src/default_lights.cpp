#include "default_lights.h"

#include <cmath>

namespace orb::detail {
namespace {

Vec3 normalized(Vec3 v) {
    const double length = std::hypot(v[0], v[1], v[2]);
    return {v[0] / length, v[1] / length, v[2] / length};
}

}  // namespace

void add_default_lights(Scene& scene, const Vec3& center, double radius) {
    struct Light {
        const char* name;
        Vec3 direction;
        double radiance;
    };
    const Light lights[] = {{"key light", {-1, 2, 1}, 0.8 * 16}, {"fill light", {1, 0.5, 0.5}, 0.3 * 16}};
    for (const Light& light : lights) {
        Material material;
        material.name = light.name;
        material.color = {0, 0, 0};
        material.emission = {light.radiance, light.radiance, light.radiance};
        scene.materials.push_back(material);
        // Unnamed like the points (the material names it): a cloud's binary
        // form then needs no name section at all.
        Sphere sphere;
        const Vec3 d = normalized(light.direction);
        for (int c = 0; c < 3; ++c) sphere.center[c] = center[c] + d[c] * 4 * radius;
        sphere.radius = radius;
        sphere.material = static_cast<std::uint32_t>(scene.materials.size() - 1);
        scene.spheres.push_back(sphere);
    }
}

}  // namespace orb::detail
