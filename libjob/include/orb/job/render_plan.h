// What a render job will do: the scene at the requested time, the renderer's
// settings and the output's, with everything a resumed EXR dictates applied
// and checked against what the front end gave (the resume contract).
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "orb/denoise/denoiser.h"
#include "orb/exr/film_exr.h"
#include "orb/exr/render_request.h"
#include "orb/render/adaptive_sampler.h"
#include "orb/render/renderer.h"
#include "orb/import/molecular.h"
#include "orb/import/sphere_styling.h"
#include "orb/job/messages.h"
#include "orb/job/request_settings.h"
#include "orb/render/development_knobs.h"
#include "orb/scene/scene.h"

namespace orb::job {

// What the front end asks of a render (orb-render's options, converted from
// its command line; render_still's settings): plain values, no parser's types.
struct PlanOptions {
    // The settings as given, each optional: a resumed render compares them
    // with its file (a setting the file fixes may be repeated, only with the
    // same value).
    GivenSettings given;
    std::string sample_range_text;    // given.sample_range as written, for messages
    std::optional<double> time_at;    // --time-at SECONDS: the scene time of a still
    // `given`, else the scene's render block, else Orb's default, with the
    // front end's camera (orb-render: orb::request::resolve_request); for a
    // fresh render.
    RequestSettings settings;
    CameraRequest resume_camera;      // the camera for a resumed render (it has no frames, so no orbit)
    std::vector<long> frames;         // --frame/--frames in order; empty: a still
    std::string resume;               // the EXR to continue (--resume), or ""
    std::optional<double> noise_threshold;  // --noise-threshold
    std::optional<double> target_error;     // --target-error
    std::string device;               // --device; "": the fastest GPU, else the CPU
    std::string kernel_dir;           // --kernel-dir; "": ORB_KERNEL_DIR's, else the installed kernels
    bool no_cache = false;            // --no-cache: kernels are built from source every run
    std::optional<exr::ExrCompression> compression;
    bool denoise = false;             // --denoise
    bool load_denoiser = true;        // false for a run that renders nothing (--missing)
    // The images will carry their exact sums (checkpoints, --time): the host memory they need.
    bool checkpoints_or_time_limit = false;
    SphereStyleOptions style;         // --color-by, --radius-by, ...: applied to each trajectory frame read
    MessageSink messages;             // warnings and notes; the library never prints
};

// The scene as the front end read it (orb-render: orb::request::read_scene
// or open_trajectory, styled): what the plan poses.
struct SceneInput {
    Scene imported;            // a trajectory's frame 1, styled
    std::string label;         // what orb:sceneFile records: the path, <stdin>, <memory>
    std::shared_ptr<const FrameSource> trajectory;  // a molecular or particle trajectory, or null
};

// Frame 1 of a trajectory as the plan read and styled it, handed to the
// pose of frame 1 (on whichever thread poses it) instead of reading and
// styling it again; once: a later pose of frame 1 reads it anew.
class HeldFrame {
public:
    explicit HeldFrame(Scene scene) : scene_(std::move(scene)) {}
    std::optional<Scene> take() {
        std::lock_guard<std::mutex> lock(mutex_);
        std::optional<Scene> taken = std::move(scene_);
        scene_.reset();
        return taken;
    }

private:
    std::mutex mutex_;
    std::optional<Scene> scene_;
};

struct RenderPlan {
    MessageSink messages;       // the front end's (PlanOptions::messages)
    Scene scene;                // at scene_time
    std::string scene_label;    // the path, or <stdin>
    std::string scene_hash;     // orb::scene_content_hash(scene)
    std::string kernel;         // orb:kernel, the kernels this run builds (orb/render/kernel_identity.h)
    double read_seconds = 0;    // reading, importing, posing and hashing the scene (set by the caller that timed it)
    double scene_time = 0;
    render::RenderConfig config;
    RequestSettings settings;  // the command line's settings, filled in from the scene
    std::uint64_t target_spp = 0;   // samples per pixel the film is to hold
    std::uint64_t first_sample = 0; // where a fresh render starts (--sample-range START)
    bool slice = false;             // --sample-range: the output is a slice, to be merged
    std::vector<exr::Pass> passes;
    bool half = false;
    exr::ExrCompression compression = exr::ExrCompression::Zip;
    // The film to continue from (--resume, or an output --skip-existing
    // continues); its metadata stays once its film is on the device.
    std::optional<exr::ExrFilm> resumed;
    std::string resumed_path;  // the file `resumed` was read from
    // --denoise: the passes include its guides, and the denoiser is loaded
    // before anything renders (not for --missing, which renders nothing),
    // shared by every frame.
    bool denoise = false;
    std::shared_ptr<denoise::Denoiser> denoiser;
    // Adaptive sampling: from the command line, else the resumed file's. Its
    // layers (variance, and samples for a noise threshold) are in `passes`.
    render::AdaptiveSettings adaptive;

    // Animations (--frame/--frames): the frames in order, and the scene as
    // read, posed anew for each frame by pose_frame.
    std::vector<long> frames;
    Scene imported;
    std::size_t frames_in_flight = 0;  // frames BackgroundWriter writes at once (0 without --frames)
    // A molecular or particle trajectory (orb/request/scene_input.h): each
    // frame is read from the file when it is posed, and `imported` stays empty.
    std::shared_ptr<const FrameSource> trajectory;
    std::shared_ptr<HeldFrame> trajectory_first;  // its frame 1, read and styled for the plan
    // --color-by, --radius-by, ...: applied to the imported scene, and to
    // each trajectory frame as it is read.
    SphereStyleOptions style;
    std::optional<exr::FrameInfo> frame;  // the frame `scene` is posed at
    // The scene differs from the one last handed to the renderer: false
    // from frame to frame of a scene without animation, whose spheres then
    // are neither copied, hashed, laid out nor uploaded again.
    bool scene_changed = true;
    // `scene` laid out for the renderer ahead of time (its tree refitted or
    // built while the last frame rendered), when it was; else set_up lays it out.
    std::optional<render::PreparedScene> prepared_scene;
};

// A frame's scene, posed and hashed: what pose_frame installs in a plan.
// pose_at reads only the plan's imported scene and settings, so the next
// frame can be posed on another thread while this one renders.
struct PosedFrame {
    long frame = 0;
    std::optional<Scene> scene;  // none for a scene without animation: the plan's own stays
    std::string hash;
    std::optional<render::PreparedScene> prepared;  // `scene` laid out by the renderer, when asked
};
PosedFrame pose_at(const RenderPlan& plan, long frame);
void install(RenderPlan& plan, PosedFrame&& posed);

// Applies the options to the scene (and for a resumed render the file's
// header: the resume contract). Throws orb::InputError for bad input or a
// resume that would not continue the same render.
RenderPlan make_render_plan(const PlanOptions& options, SceneInput scene, const render::DevelopmentKnobs& knobs);

// Whether the plan renders frames of an animation (--frame, --frames).
inline bool renders_frames(const PlanOptions& options) { return !options.frames.empty(); }

// Whether each frame's scene differs from the last: an animated scene, a
// trajectory of more than one frame, or one whose camera --orbit turns.
bool changes_per_frame(const RenderPlan& plan);

// Poses the plan at `frame`: the scene at frame / fps (checked against the
// scene limits again) with the command line's camera, its hash, the frame's seed. Throws orb::InputError.
void pose_frame(RenderPlan& plan, long frame);  // install(plan, pose_at(plan, frame))
// Whether the plan's scene is posed at `frame` already.
bool posed_at(const RenderPlan& plan, long frame);

// The orb:* metadata for an image of this plan (render seconds and device filled by the caller).
// orb:version is Orb's version (the project's, as every tool's --version says).
exr::ExrMetadata plan_metadata(const RenderPlan& plan);

// What the output of `frame` (none: the one output of a still) is asked to
// hold. The scene's identity is computed when the judgement needs it, by
// posing the plan at the frame (which rendering it would do anyway).
exr::RenderRequest request_for(RenderPlan& plan, std::optional<long> frame);

}  // namespace orb::job
