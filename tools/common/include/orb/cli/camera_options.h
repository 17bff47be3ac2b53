// The camera from the command line (docs/orb-render.md, "Camera"): options
// that replace parts of a scene's camera after the scene is read and posed,
// and the turntable that turns it frame by frame. orb-render, orb-frames
// and orb-import read them from here, so they mean the same in each.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "orb/scene/scene.h"

namespace orb::cli {

struct CameraOptions {
    std::optional<Vec3> position;  // --camera-position X,Y,Z
    std::optional<Vec3> look_at;   // --look-at X,Y,Z (Camera::target)
    std::optional<Vec3> up;        // --up X,Y,Z
    std::optional<double> vfov_deg, aperture, focus_distance;
    std::optional<double> orthographic_height;  // --orthographic HEIGHT
    bool auto_camera = false;                   // --auto-camera: frame the spheres anew

    bool operator==(const CameraOptions&) const = default;  // CameraOptions{}: none given
};

// Adds the options above, each value checked on its own (finite, in range).
void add_camera_options(CLI::App& app, CameraOptions& options);

// The given parts replace `camera`'s, the others stay (--auto-camera aside).
// Throws orb::InputError naming `source` and the option when the result has
// no view direction (position = look-at) or no roll (up parallel to the view).
void apply_camera_options(const CameraOptions& options, Camera& camera, const std::string& source);

// The same on a scene whose image is width x height, --auto-camera included:
// --up, --vfov, --aperture and --orthographic first; then --auto-camera
// frames the scene's spheres that emit no light (all of them if every one
// does) by the automatic camera's rule (orb::frame_spheres), along the
// camera's view direction with its up, for this image and field of view,
// setting position, look-at and focus distance; then --camera-position,
// --look-at and --focus-distance, which win over it.
void apply_camera_options(const CameraOptions& options, Scene& scene, int width, int height,
                          const std::string& source);

// "X,Y,Z": three finite numbers within the scene limits; none otherwise.
std::optional<Vec3> parse_point(const std::string& text);

}  // namespace orb::cli
