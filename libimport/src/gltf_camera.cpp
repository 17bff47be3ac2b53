// glTF cameras -> the Orb camera, and the automatic camera for assets that
// have none (docs/gltf.md, "Cameras").
#include <algorithm>
#include <cmath>
#include <numbers>

#include "gltf_internal.h"
#include "orb/scene/auto_framing.h"
#include "orb/scene/detail/json_text.h"
#include "orb/scene/scene_json.h"

namespace orb::gltf {
namespace {

// glTF's aspect ratio sets the width; the height stays at Orb's default.
constexpr int kDefaultHeight = 480;

using detail::format_number;

// The default image for an aspect ratio: kDefaultHeight rows, as many columns as the ratio asks (within Orb's limits).
void set_image_aspect(double aspect, Scene& scene) {
    scene.render.height = kDefaultHeight;
    // Clamped before rounding, so that no ratio overflows the integer.
    scene.render.width = int(std::lround(std::clamp(kDefaultHeight * aspect, 1.0, double(kMaxImageSide))));
}

void convert_perspective(const tinygltf::PerspectiveCamera& camera, const std::string& label, Scene& scene,
                         const Diagnostics& diagnostics) {
    const double yfov = camera.yfov;
    if (!(yfov > 0) || !(yfov < std::numbers::pi))
        diagnostics.fail(label + ": yfov " + std::to_string(yfov) + " must be in (0, pi) radians");
    scene.camera.vfov_deg = yfov * 180.0 / std::numbers::pi;
    const double aspect = camera.aspectRatio;
    if (aspect > 0 && std::isfinite(aspect)) set_image_aspect(aspect, scene);
}

// xmag and ymag are half the view's width and height. The view keeps its
// height, 2 ymag; its width follows the image, whose default aspect is
// xmag/ymag (as a perspective camera's aspectRatio sets it).
void convert_orthographic(const tinygltf::OrthographicCamera& camera, const std::string& label, Scene& scene,
                          Diagnostics& diagnostics) {
    const double xmag = camera.xmag, ymag = camera.ymag;
    // Negative magnifications would mirror the image; glTF says they should not be used.
    if (!(ymag > 0) || !std::isfinite(ymag))
        diagnostics.fail(label + ": orthographic ymag " + format_number(ymag) + " must be > 0 (half the view's height)");
    if (!(xmag > 0) || !std::isfinite(xmag))
        diagnostics.fail(label + ": orthographic xmag " + format_number(xmag) + " must be > 0 (half the view's width)");
    scene.camera.orthographic_height = 2 * ymag;
    const double aspect = xmag / ymag;
    set_image_aspect(aspect, scene);
    const double image_aspect = double(scene.render.width) / double(scene.render.height);
    // Rounding to whole pixels moves the width by at most half a pixel; more means the width was clamped.
    if (std::fabs(image_aspect - aspect) * scene.render.height > 0.5)
        diagnostics.lossy(label + ": orthographic xmag/ymag " + format_number(aspect) + " needs an image " +
                          format_number(std::round(kDefaultHeight * aspect)) + " pixels wide; it is " +
                          std::to_string(scene.render.width) + "x" + std::to_string(scene.render.height) +
                          ", so the view keeps its height 2 ymag = " + format_number(2 * ymag) + " and is " +
                          format_number(2 * ymag * image_aspect) + " wide, not 2 xmag = " + format_number(2 * xmag));
}

}  // namespace

void convert_camera(const tinygltf::Camera& camera, const std::string& name, const Matrix4& world,
                    const AnimVec3& scene_center, Scene& scene, Diagnostics& diagnostics) {
    const std::string label = "camera '" + name + "'";
    if (camera.type == "perspective")
        convert_perspective(camera.perspective, label, scene, diagnostics);
    else if (camera.type == "orthographic")
        convert_orthographic(camera.orthographic, label, scene, diagnostics);
    else
        diagnostics.fail(label + " has type '" + camera.type + "', expected \"perspective\" or \"orthographic\"");

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
