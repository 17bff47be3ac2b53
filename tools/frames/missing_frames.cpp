#include "missing_frames.h"

#include "orb/job/scene_pose.h"
#include "orb/request/scene_input.h"
#include "orb/scene/scene_json.h"

namespace orb::frames {

MissingFrames::MissingFrames(const std::string& scene_path, const request::RequestOptions& options,
                             const std::string& frames, const cli::SceneReading& reading,
                             const SphereStyleOptions& style)
    : style_(style) {
    // The orbit is checked before a scene of millions of spheres is read.
    settings_ = request::resolve_request(options, nullptr, &frames, true);
    if (scene_path.empty()) return;
    job::SceneInput input = request::read_scene_input(scene_path, reading);
    trajectory_ = std::move(input.trajectory);
    label_ = std::move(input.label);
    scene_ = std::move(input.imported);
    const auto style_scene = [&] { return apply_sphere_styling(*scene_, style_, label_); };
    styled_ = trajectory_ ? job::for_frame(1, style_scene) : style_scene();
    settings_ = request::resolve_request(options, &scene_->render, &frames, true);
}

exr::SceneIdentity MissingFrames::identity_at(long frame) {
    if (still_identity_) return *still_identity_;
    // A frame past a trajectory's end is an error, as in orb-render.
    // A trajectory's frame 1 is the scene read and styled already.
    const bool read_frame = trajectory_ && frame != 1;
    Scene posed = job::for_frame(frame, [&] {
        Scene scene = read_frame   ? job::trajectory_frame(*trajectory_, frame, label_)
                      : trajectory_ ? *scene_
                                    : job::pose_scene(*scene_, job::frame_time(frame, settings_.fps), label_);
        if (read_frame) apply_sphere_styling(scene, style_, label_);
        job::apply_camera_request(scene, settings_, frame, label_);
        return scene;
    });
    exr::SceneIdentity identity =
        job::scene_identity(posed, scene_content_hash(posed), *settings_.width, *settings_.height);
    const bool frames_differ = trajectory_ && trajectory_->frame_count() > 1;
    if (scene_->animation.empty() && !frames_differ && !job::camera_moves(settings_)) still_identity_ = identity;
    return identity;
}

exr::OutputJudgement MissingFrames::judge(const std::string& path, long frame) {
    exr::RenderRequest request = settings_.request(frame);
    if (scene_) request.scene = [this, frame] { return identity_at(frame); };
    return exr::judge_output(path, request);
}

}  // namespace orb::frames
