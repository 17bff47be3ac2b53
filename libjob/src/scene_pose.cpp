#include "orb/job/scene_pose.h"

#include <sstream>

#include "orb/exr/camera_matrices.h"
#include "orb/scene/animation.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"

namespace orb::job {

Scene trajectory_frame(const FrameSource& frames, long frame, const std::string& label) {
    require_trajectory_frames(frames, {frame}, label);
    Scene scene = frames.frame(static_cast<std::size_t>(frame - 1));
    validate_scene(scene, label);  // the caller names the frame (for_frame)
    return scene;
}

void require_trajectory_frames(const FrameSource& source, const std::vector<long>& frames, const std::string& label) {
    const std::size_t count = source.frame_count();
    for (long frame : frames)
        if (frame < 1 || static_cast<std::size_t>(frame) > count)
            throw InputError(label + ": has " + std::to_string(count) + (count == 1 ? " frame" : " frames") + " (1-" +
                             std::to_string(count) + "); there is no frame " + std::to_string(frame) +
                             " (frame 1 is the file's first)");
}

Scene pose_scene(const Scene& imported, double seconds, const std::string& label) {
    Scene posed = scene_at_time(imported, seconds);
    if (!imported.animation.empty()) {
        std::ostringstream at;
        at << label << " at " << seconds << " s";
        validate_scene(posed, at.str());
    }
    return posed;
}

Scene pose_scene(Scene&& imported, double seconds, const std::string& label) {
    if (imported.animation.empty()) return std::move(imported);
    return pose_scene(static_cast<const Scene&>(imported), seconds, label);
}

void apply_camera_request(Scene& posed, const RequestSettings& settings, std::optional<long> frame,
                          const std::string& label) {
    // The image's size: the front end's, else the scene's (orb-frames without --scene compares no camera).
    if (settings.camera.apply)
        settings.camera.apply(posed, settings.width.value_or(posed.render.width),
                              settings.height.value_or(posed.render.height), label);
    if (settings.camera.turn && frame) posed.camera = settings.camera.turn(posed.camera, *frame);
}

bool camera_moves(const RequestSettings& settings) { return static_cast<bool>(settings.camera.turn); }

exr::SceneIdentity scene_identity(const Scene& posed, const std::string& hash, int width, int height) {
    return {hash, exr::world_to_camera(posed.camera), exr::world_to_ndc(posed.camera, width, height)};
}

}  // namespace orb::job
