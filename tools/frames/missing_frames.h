// orb-frames --missing: each frame's file judged against the render that
// orb-render would make with the same options (orb::exr::judge_output, the
// definition orb-render --skip-existing uses), reading headers only.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "orb/cli/scene_reading.h"
#include "orb/exr/render_request.h"
#include "orb/request/request_options.h"
#include "orb/job/request_settings.h"
#include "orb/import/molecular.h"
#include "orb/scene/scene.h"
#include "orb/import/sphere_styling.h"

namespace orb::frames {

class MissingFrames {
public:
    // Reads `scene_path` as orb-render does, as `reading` asks, when it is not
    // empty (throws orb::InputError for a bad scene, and for one without
    // spheres unless --allow-empty); without it the scene, its camera and what its render
    // block would fill in are not compared. `frames` is the frame list
    // judged: the range of --orbit unless --orbit-frames gives it. A
    // molecular trajectory is read frame by frame, as orb-render reads it,
    // and each scene is styled (--color-by, ...) as orb-render styles it.
    MissingFrames(const std::string& scene_path, const request::RequestOptions& options, const std::string& frames,
                  const cli::SceneReading& reading, const SphereStyleOptions& style = {});

    exr::OutputJudgement judge(const std::string& path, long frame);

    // What styling the scene (a trajectory's frame 1) did, for --legend.
    const SphereStyleResult& styled() const { return styled_; }
    // A trajectory of several frames: each is styled by its own range.
    bool frames_differ() const { return trajectory_ && trajectory_->frame_count() > 1; }

private:
    exr::SceneIdentity identity_at(long frame);

    std::optional<Scene> scene_;
    std::shared_ptr<const FrameSource> trajectory_;
    std::string label_;
    SphereStyleOptions style_;
    SphereStyleResult styled_;
    job::RequestSettings settings_;
    std::optional<exr::SceneIdentity> still_identity_;  // a scene without animation or orbit is the same at every frame
};

}  // namespace orb::frames
