#include "missing_frames.h"

#include "orb/request/scene_input.h"
#include "orb/scene/scene_json.h"

namespace orb::frames {

MissingFrames::MissingFrames(const std::string& scene_path, const request::RequestOptions& options,
                             bool allow_empty) {
    if (!scene_path.empty()) scene_ = request::read_scene(scene_path, label_, allow_empty);
    settings_ = request::resolve_request(options, scene_ ? &scene_->render : nullptr);
}

exr::SceneIdentity MissingFrames::identity_at(long frame) {
    if (still_identity_) return *still_identity_;
    const Scene posed = request::pose_scene(*scene_, request::frame_time(frame, settings_.fps), label_);
    exr::SceneIdentity identity =
        request::scene_identity(posed, scene_content_hash(posed), *settings_.width, *settings_.height);
    if (scene_->animation.empty()) still_identity_ = identity;
    return identity;
}

exr::OutputJudgement MissingFrames::judge(const std::string& path, long frame) {
    exr::RenderRequest request = settings_.request(frame);
    if (scene_) request.scene = [this, frame] { return identity_at(frame); };
    return exr::judge_output(path, request);
}

}  // namespace orb::frames
