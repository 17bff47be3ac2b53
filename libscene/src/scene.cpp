#include "orb/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace orb {

bool Environment::operator==(const Environment& other) const {
    const bool same_image = image == other.image || (image && other.image && *image == *other.image);
    return kind == other.kind && color == other.color && map == other.map && intensity == other.intensity &&
           rotation_deg == other.rotation_deg && same_image;
}

bool SphereProperty::operator==(const SphereProperty& other) const {
    const auto same = [](float a, float b) { return a == b || (!has_value(a) && !has_value(b)); };
    return name == other.name && labels == other.labels &&
           std::equal(values.begin(), values.end(), other.values.begin(), other.values.end(), same);
}

namespace {

bool any_positive(const Vec3& v) { return v[0] > 0 || v[1] > 0 || v[2] > 0; }

}  // namespace

bool environment_emits(const Environment& environment) {
    switch (environment.kind) {
        case EnvironmentKind::None: return false;
        case EnvironmentKind::Color: return any_positive(environment.color);
        case EnvironmentKind::Map: break;
    }
    if (!(environment.intensity > 0)) return false;
    if (!environment.image) return true;  // not loaded yet: assume the map is not black
    for (float value : environment.image->rgb)
        if (value > 0) return true;
    return false;
}

bool scene_has_light(const Scene& scene) {
    if (environment_emits(scene.environment)) return true;
    for (const Sphere& sphere : scene.spheres)
        if (sphere.material < scene.materials.size() && any_positive(scene.materials[sphere.material].emission))
            return true;
    return false;
}

double smallptgpu_vfov_deg() { return 2.0 * std::atan(std::numbers::pi / 8.0) * 180.0 / std::numbers::pi; }

bool has_roughness(MaterialType type) { return type == MaterialType::Dielectric || type == MaterialType::Pbr; }

bool has_metallic(MaterialType type) { return type == MaterialType::Pbr; }

}  // namespace orb
