#include "scene_layout.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace orb::render {
namespace {

float f(double value) { return static_cast<float>(value); }

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double length(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
Float4 to_float4(const Vec3& a, double w) { return {f(a[0]), f(a[1]), f(a[2]), f(w)}; }

KernelMaterial kernel_material(MaterialType type)
{
    switch (type) {
    case MaterialType::Mirror: return KernelMaterial::Mirror;
    case MaterialType::Dielectric: return KernelMaterial::Dielectric;
    case MaterialType::Diffuse: break;
    }
    return KernelMaterial::Diffuse;
}

}  // namespace

std::size_t SceneLayout::bytes() const
{
    return (packets.size() + records.size()) * sizeof(Float4) + lights.size() * sizeof(std::int32_t);
}

SceneLayout layout_scene(const Scene& scene)
{
    SceneLayout layout;
    layout.sphere_count = static_cast<int>(scene.spheres.size());
    layout.packet_count = (layout.sphere_count + 3) / 4;
    // Unused lanes: radius^2 = -1 makes the discriminant negative, so they never hit.
    layout.packets.assign(static_cast<size_t>(layout.packet_count) * 4, Float4{0.0f, 0.0f, 0.0f, -1.0f});
    layout.records.reserve(scene.spheres.size() * 3);

    for (size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& sphere = scene.spheres[i];
        const std::string which = "sphere " + std::to_string(i) + (sphere.name.empty() ? "" : " ('" + sphere.name + "')");
        if (!(sphere.radius > 0.0) || !std::isfinite(sphere.radius))
            throw std::runtime_error(which + " has radius " + std::to_string(sphere.radius) +
                                     "; a positive, finite radius is required");
        if (sphere.material >= scene.materials.size())
            throw std::runtime_error(which + " uses material " + std::to_string(sphere.material) + " but the scene has " +
                                     std::to_string(scene.materials.size()) + " materials");
        const Material& material = scene.materials[sphere.material];

        const size_t packet = i / 4, lane = i % 4;
        for (int axis = 0; axis < 3; ++axis) layout.packets[packet * 4 + axis][lane] = f(sphere.center[axis]);
        layout.packets[packet * 4 + 3][lane] = f(sphere.radius * sphere.radius);

        layout.records.push_back(to_float4(sphere.center, sphere.radius));
        layout.records.push_back(
            to_float4(material.color, static_cast<double>(static_cast<int>(kernel_material(material.type)))));
        layout.records.push_back(to_float4(material.emission, material.ior));

        const Vec3& e = material.emission;
        if (e[0] > 0.0 || e[1] > 0.0 || e[2] > 0.0) layout.lights.push_back(static_cast<std::int32_t>(i));
    }
    return layout;
}

CameraLayout layout_camera(const Camera& camera, int width, int height)
{
    const Vec3 towards = sub(camera.target, camera.position);
    const double distance = length(towards);
    if (!(distance > 0.0) || !std::isfinite(distance))
        throw std::runtime_error("the camera's target equals its position, so it has no viewing direction");
    const Vec3 forward = scaled(towards, 1.0 / distance);

    // An up vector parallel to the view direction leaves the roll undefined:
    // fall back to the world axis least aligned with the view.
    Vec3 right = cross(forward, camera.up);
    if (length(right) < 1e-9 * std::max(1.0, length(camera.up))) {
        const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        int best = 0;
        for (int a = 1; a < 3; ++a)
            if (std::abs(forward[a]) < std::abs(forward[best])) best = a;
        right = cross(forward, axes[best]);
    }
    right = scaled(right, 1.0 / length(right));
    const Vec3 up = cross(right, forward);

    const double half_height = std::tan(camera.vfov_deg * std::numbers::pi / 360.0);
    const double half_width = half_height * static_cast<double>(width) / static_cast<double>(height);

    CameraLayout layout;
    layout.origin = to_float4(camera.position, 0.0);
    layout.right = to_float4(right, 0.0);
    layout.up = to_float4(up, 0.0);
    layout.forward = to_float4(forward, 0.0);
    layout.lens = {f(half_width), f(half_height), f(std::max(0.0, camera.aperture) * 0.5),
                   f(camera.focus_distance > 0.0 ? camera.focus_distance : distance)};
    return layout;
}

}  // namespace orb::render
