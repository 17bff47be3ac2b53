// glTF cameras -> the Orb camera, and the automatic camera for assets that
// have none (docs/gltf.md, "Cameras").
#include <algorithm>
#include <cmath>
#include <numbers>

#include "gltf_internal.h"
#include "orb/scene/auto_framing.h"
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
    // From +z looking down -z, +y up (orb/scene/auto_framing.h: outliers left out, fitted to the aspect ratio).
    const FramingView view{{0, 0, 1}, {0, 1, 0}, scene.camera.vfov_deg, scene.render.width, scene.render.height};
    const std::optional<Framing> framing =
        frame_spheres(scene.spheres, view, [&distant](std::size_t i) { return distant.count(i) != 0; });
    if (!framing) return;
    scene.camera.position = framing->position;
    scene.camera.target = framing->target;
    scene.camera.up = {0, 1, 0};
    scene.camera.focus_distance = framing->distance;
}

}  // namespace orb::gltf
