// The camera's orthonormal frame, the extent of its view and its lens: what
// the renderer's device camera (librender) and the worldToCamera/worldToNDC
// matrices stored beside the image (libexr) both read, so that the image and
// the matrices describe one camera. Conventions in docs/scene-format.md.
#pragma once

#include "orb/scene/scene.h"

namespace orb {

struct CameraFrame {
    Vec3 forward{};  // unit, from the position towards the target
    Vec3 right{};    // unit, forward x up: the image's +x
    Vec3 up{};       // unit, right x forward: the image's +y (the scene's up made orthogonal to the view)
    double target_distance = 0;  // |target - position|
};

// The sine of the angle between a view direction and an up direction, both
// non-zero (they are made unit with std::hypot, so huge but finite
// coordinates do not overflow). At or below kMinViewUpSine the camera's roll
// is undefined: scene validation and the camera options refuse such a pose.
double view_up_sine(const Vec3& forward, const Vec3& up);
inline constexpr double kMinViewUpSine = 1e-9;

// The frame of `camera`. An up parallel to the view leaves the roll
// undefined (scene validation refuses it; a pose reached by animation may
// still come close): then right is taken from the world axis least aligned
// with the view. Throws std::runtime_error for a camera without a viewing
// direction (its target equals its position, or is not finite).
CameraFrame camera_frame(const Camera& camera);

// Half the view's width and height: perspective, on the image plane at unit
// distance (the tangents of the half-angles, vfov_deg vertically, the width
// from the image's aspect ratio); orthographic (orthographic_height > 0), in
// scene units at every distance. Throws std::invalid_argument unless the
// image size is positive.
struct ViewExtents {
    bool orthographic = false;
    double half_width = 0;
    double half_height = 0;
};
ViewExtents view_extents(const Camera& camera, int width, int height);

// The thin lens: its radius (half the aperture; 0 is a pinhole) and the
// distance in focus, the camera's own or else the target's.
struct CameraLens {
    double radius = 0;
    double focus_distance = 0;
};
CameraLens camera_lens(const Camera& camera, const CameraFrame& frame);

}  // namespace orb
