#include "orb/cli/orbit_options.h"

#include "orb/cli/frame_spec.h"
#include "orb/cli/number_checks.h"
#include "orb/cli/tool_main.h"
#include "orb/scene/camera_orbit.h"

namespace orb::cli {

void add_orbit_options(CLI::App& app, OrbitOptions& o) {
    app.add_option("--orbit", o.degrees,
                   "Turntable: turn the camera this many degrees about the look-at point and the up axis over the "
                   "frames (frame f at DEGREES*(f-first)/(last-first+1))")
        ->check(finite_number_in(-1e6, 1e6, "a number of degrees"))
        ->option_text("DEGREES")
        ->group("Camera");
    app.add_option("--orbit-frames", o.frames,
                   "The whole animation's frame list the orbit spans (default: --frames); needed with --frame N")
        ->option_text("LIST")
        ->group("Camera");
}

double Orbit::angle_deg(long frame) const { return orbit_angle_deg(degrees, frame, first, last); }

Camera Orbit::turn(const Camera& camera, long frame) const { return orbit_camera(camera, angle_deg(frame)); }

std::optional<Orbit> resolve_orbit(const OrbitOptions& o, const std::string* animation_frames, bool renders_frames) {
    if (!o.degrees) {
        if (o.frames) throw UsageError("--orbit-frames LIST goes with --orbit DEGREES");
        return std::nullopt;
    }
    if (!renders_frames)
        throw UsageError("--orbit turns the camera over the frames of an animation: give --frames SPEC (or --frame N "
                         "with --orbit-frames LIST)");
    const std::string* list = o.frames ? &*o.frames : animation_frames;
    if (!list)
        throw UsageError("--orbit with --frame N needs --orbit-frames LIST: the whole animation's frames, whose "
                         "range the orbit spans (e.g. --orbit-frames 1-240)");
    FrameSpec spec;
    try {
        spec = parse_frame_spec(*list);
    } catch (const UsageError& e) {
        throw UsageError(std::string(o.frames ? "--orbit-frames: " : "--frames: ") + e.what());
    }
    return Orbit{*o.degrees, spec.lowest, spec.highest};
}

}  // namespace orb::cli
