// glTF cameras -> the Orb camera, and the automatic camera for assets that
// have none (docs/gltf.md, "Cameras").
#include <algorithm>
#include <cmath>
#include <numbers>

#include "gltf_internal.h"
#include "orb/scene/scene_json.h"

namespace orb::gltf {
namespace {

// glTF's aspect ratio sets the width; the height stays at Orb's default.
constexpr int kDefaultHeight = 480;

}  // namespace

void convert_camera(const tinygltf::Camera& camera, const std::string& name, const Matrix4& world,
                    const AnimVec3& scene_center, Scene& scene, const Diagnostics& diagnostics) {
    const std::string label = "camera '" + name + "'";
    if (camera.type == "orthographic")
        diagnostics.fail(label + " is orthographic; Orb renders perspective cameras only (pick another with --camera)");
    if (camera.type != "perspective")
        diagnostics.fail(label + " has type '" + camera.type + "', expected \"perspective\"");
    const double yfov = camera.perspective.yfov;
    if (!(yfov > 0) || !(yfov < std::numbers::pi))
        diagnostics.fail(label + ": yfov " + std::to_string(yfov) + " must be in (0, pi) radians");
    scene.camera.vfov_deg = yfov * 180.0 / std::numbers::pi;
    const double aspect = camera.perspective.aspectRatio;
    if (aspect > 0 && std::isfinite(aspect)) {
        scene.render.height = kDefaultHeight;
        scene.render.width = int(std::clamp(std::lround(kDefaultHeight * aspect), 1L, long(kMaxImageSide)));
    }

    // The camera looks down its node's -z with +y up.
    AnimVec3 forward = detail::transform_direction(world, {0, 0, -1});
    AnimVec3 up = detail::transform_direction(world, {0, 1, 0});
    const double forward_length = detail::length3(forward);
    if (!(forward_length > 0)) diagnostics.fail(label + ": its node's transform collapses the view direction");
    for (double& c : forward) c /= forward_length;
    const double along = detail::dot3(up, forward);
    for (int c = 0; c < 3; ++c) up[c] -= along * forward[c];
    const double up_length = detail::length3(up);
    if (!(up_length > 1e-12)) diagnostics.fail(label + ": its node's transform collapses the up direction");
    const AnimVec3 position = detail::transform_point(world, {0, 0, 0});
    const AnimVec3 to_center{scene_center[0] - position[0], scene_center[1] - position[1],
                             scene_center[2] - position[2]};
    double distance = detail::dot3(to_center, forward);
    if (!(distance > 0) || !std::isfinite(distance)) distance = 1.0;
    scene.camera.position = position;
    for (int c = 0; c < 3; ++c) {
        scene.camera.target[c] = position[c] + forward[c] * distance;
        scene.camera.up[c] = up[c] / up_length;
    }
    scene.camera.focus_distance = distance;
}

void automatic_camera(Scene& scene, const std::set<std::size_t>& distant) {
    AnimVec3 lo{}, hi{};
    bool any = false;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        if (distant.count(i)) continue;
        const Sphere& s = scene.spheres[i];
        for (int c = 0; c < 3; ++c) {
            const double a = s.center[c] - s.radius, b = s.center[c] + s.radius;
            lo[c] = any ? std::min(lo[c], a) : a;
            hi[c] = any ? std::max(hi[c], b) : b;
        }
        any = true;
    }
    if (!any) return;
    const AnimVec3 center{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
    const double half_diagonal =
        std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2])) / 2;
    // Fit the bounding sphere of the box inside the narrower field of view.
    const double half_v = scene.camera.vfov_deg * std::numbers::pi / 360.0;
    const double aspect = double(scene.render.width) / double(scene.render.height);
    const double half_h = std::atan(std::tan(half_v) * aspect);
    const double distance = half_diagonal / std::sin(std::min(half_v, half_h));
    scene.camera.position = {center[0], center[1], center[2] + distance};
    scene.camera.target = center;
    scene.camera.up = {0, 1, 0};
    scene.camera.focus_distance = distance;
}

}  // namespace orb::gltf
