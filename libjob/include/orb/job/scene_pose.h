// A scene posed for an output: at a time or a frame, with the camera the
// front end asks for, and what an output records of it. Every tool that
// renders or judges frame f poses it here, so they agree on its identity.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "orb/exr/render_request.h"
#include "orb/import/molecular.h"
#include "orb/job/request_settings.h"
#include "orb/scene/error.h"
#include "orb/scene/scene.h"

namespace orb::job {

// Runs `work`, which reads, poses or styles the scene of frame `frame`: an
// orb::InputError it throws is thrown again with "frame N: " before its
// message, so that an error met at frame 3 of 240 says which frame it was.
template <typename Work>
auto for_frame(long frame, Work&& work) -> decltype(work()) {
    try {
        return work();
    } catch (const InputError& e) {
        throw InputError("frame " + std::to_string(frame) + ": " + e.what());
    }
}

// Frame `frame` (1-based) of a trajectory, checked against the scene limits.
// Throws orb::InputError naming the frames there are for one past the end.
Scene trajectory_frame(const FrameSource& frames, long frame, const std::string& label);

// Throws orb::InputError when a frame of `frames` is not one of the file's 1..N.
void require_trajectory_frames(const FrameSource& source, const std::vector<long>& frames, const std::string& label);

// The scene at `seconds`, checked against the scene limits again when it is
// animated (posing multiplies scales and adds offsets). Throws orb::InputError.
Scene pose_scene(const Scene& imported, double seconds, const std::string& label);
// The same for a scene the caller gives up: one without animation is its
// own pose, moved rather than copied (ten million spheres are a gigabyte).
Scene pose_scene(Scene&& imported, double seconds, const std::string& label);

// The camera the front end asks for (RequestSettings::camera), on a posed
// scene: it replaces parts of the scene's camera, then the orbit turns it to
// `frame` (none: a still, which has no orbit). The same for every tool, so
// frame f has one camera whoever renders or judges it. Throws
// orb::InputError naming the option that leaves the camera without a view.
void apply_camera_request(Scene& posed, const RequestSettings& settings, std::optional<long> frame,
                          const std::string& label);

// Whether the camera differs from frame to frame although the scene does not (--orbit).
bool camera_moves(const RequestSettings& settings);

// orb:sceneHash and the camera matrices of a posed scene at an image size.
exr::SceneIdentity scene_identity(const Scene& posed, const std::string& hash, int width, int height);

}  // namespace orb::job
