#include "orb/scene/camera_frame.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace orb {

double view_up_sine(const Vec3& forward, const Vec3& up) {
    const double forward_length = std::hypot(forward[0], forward[1], forward[2]);
    const double up_length = std::hypot(up[0], up[1], up[2]);
    const Vec3 f{forward[0] / forward_length, forward[1] / forward_length, forward[2] / forward_length};
    const Vec3 u{up[0] / up_length, up[1] / up_length, up[2] / up_length};
    return std::hypot(f[1] * u[2] - f[2] * u[1], f[2] * u[0] - f[0] * u[2], f[0] * u[1] - f[1] * u[0]);
}

CameraFrame camera_frame(const Camera& camera) {
    CameraFrame frame;
    const Vec3 towards = vec3::sub(camera.target, camera.position);
    frame.target_distance = vec3::length(towards);
    if (!(frame.target_distance > 0.0) || !std::isfinite(frame.target_distance))
        throw std::runtime_error("the camera's target equals its position, so it has no viewing direction");
    frame.forward = vec3::normalized(towards);

    Vec3 right = vec3::cross(frame.forward, camera.up);
    if (vec3::length(right) < 1e-9 * std::max(1.0, vec3::length(camera.up))) {
        int least = 0;
        for (int axis = 1; axis < 3; ++axis)
            if (std::fabs(frame.forward[axis]) < std::fabs(frame.forward[least])) least = axis;
        Vec3 world_axis{0.0, 0.0, 0.0};
        world_axis[least] = 1.0;
        right = vec3::cross(frame.forward, world_axis);
    }
    frame.right = vec3::normalized(right);
    frame.up = vec3::cross(frame.right, frame.forward);
    return frame;
}

ViewExtents view_extents(const Camera& camera, int width, int height) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("image size must be positive");
    ViewExtents view;
    view.orthographic = camera.orthographic_height > 0.0;
    view.half_height = view.orthographic ? camera.orthographic_height / 2
                                         : std::tan(camera.vfov_deg * std::numbers::pi / 360.0);
    view.half_width = view.half_height * width / height;
    return view;
}

CameraLens camera_lens(const Camera& camera, const CameraFrame& frame) {
    return {std::max(0.0, camera.aperture) * 0.5,
            camera.focus_distance > 0.0 ? camera.focus_distance : frame.target_distance};
}

}  // namespace orb
