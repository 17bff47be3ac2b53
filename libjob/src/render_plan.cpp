#include "orb/job/render_plan.h"

#include <algorithm>
#include <memory>
#include <mutex>
#include <sstream>

#include "orb/exr/render_request.h"
#include "orb/job/background_writer.h"
#include "orb/job/frame_warnings.h"
#include "orb/job/scene_pose.h"
#include "orb/render/kernel_identity.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"
#include "orb/tables/render_names.h"

namespace orb::job {
namespace {

// The names come from the command line or a film's header, both checked
// against the same tables (orb/tables/render_names.h) before they get here.
render::IntegratorMode parse_mode(const std::string& name) {
    return device::value_in(device::kIntegratorModeNames, name).value();
}

render::SamplerKind parse_sampler(const std::string& name) {
    return device::value_in(device::kSamplerNames, name).value();
}

// A setting the resumed file fixes may be repeated on the command line, but
// only with the same value.
template <typename T>
void require_same(const std::optional<T>& given, const T& in_file, const std::string& option,
                  const std::string& attribute, const std::string& path) {
    if (given && *given != in_file) {
        std::ostringstream message;
        message << path << ": " << option << " " << *given << " differs from the resumed render's " << attribute
                << " " << in_file << "; drop " << option << " to continue it";
        throw InputError(message.str());
    }
}

// The layers the output will hold, and with them the film channels the
// kernels compute (the others would never be written).
// --denoise needs the albedo and normal the denoiser is guided by.
void set_passes(RenderPlan& plan, std::vector<exr::Pass> passes) {
    if (plan.denoise)
        for (exr::Pass guide : {exr::Pass::Albedo, exr::Pass::Normal})
            if (!exr::contains(passes, guide)) passes.push_back(guide);
    passes = exr::parse_passes(exr::format_passes(passes));  // back in the documented order
    plan.passes = std::move(passes);
    plan.config.film_channels = film::channels_for(plan.passes);
}

// Adaptive sampling reads the variance, and with a noise threshold the
// pixels' sample counts, at its decisions; the output keeps both, so that
// --resume and orb-merge continue from what it decided on.
void apply_adaptive(const PlanOptions& o, RenderPlan& plan) {
    const exr::ExrMetadata* file = plan.resumed ? &plan.resumed->metadata : nullptr;
    plan.adaptive.noise_threshold = o.noise_threshold ? o.noise_threshold : file ? file->noise_threshold : std::nullopt;
    plan.adaptive.target_error = o.target_error ? o.target_error : file ? file->target_error : std::nullopt;
    if (!plan.adaptive.any()) return;
    std::vector<exr::Pass> passes = plan.passes;
    passes.push_back(exr::Pass::Beauty);
    passes.push_back(exr::Pass::Variance);
    if (plan.adaptive.noise_threshold) passes.push_back(exr::Pass::Samples);
    std::vector<exr::Pass> ordered;
    for (exr::Pass pass : exr::all_passes())
        if (exr::contains(passes, pass)) ordered.push_back(pass);
    set_passes(plan, std::move(ordered));
    plan.config.adaptive = plan.adaptive.noise_threshold.has_value();
}

void apply_resume(const PlanOptions& o, const Scene& imported, RenderPlan& plan) {
    const std::string& path = o.resume;
    exr::ExrFilm file = exr::read_film_exr(path);
    const exr::ExrMetadata& m = file.metadata;

    require_same(o.time_at, m.scene_time, "--time-at", "orb:sceneTime", path);
    plan.scene_time = m.scene_time;
    plan.scene = pose_scene(imported, plan.scene_time, plan.scene_label);
    // The camera options as for a fresh render (--orbit needs frames, which --resume excludes):
    // a resumed file continues only the same view, as its hash says.
    if (o.resume_camera.apply) o.resume_camera.apply(plan.scene, file.film.width, file.film.height, plan.scene_label);
    plan.scene_hash = scene_content_hash(plan.scene);
    if (plan.scene_hash != m.scene_hash)
        throw InputError(path + ": was rendered from a different scene (orb:sceneHash " + m.scene_hash + ", from " +
                         m.scene_file + "); " + plan.scene_label + " hashes to " + plan.scene_hash);

    const GivenSettings& given = o.given;
    require_same(given.width, file.film.width, "--width", "width", path);
    require_same(given.height, file.film.height, "--height", "height", path);
    require_same(given.seed, m.seed, "--seed", "orb:seed", path);
    require_same(given.mode, m.mode, "--mode", "orb:mode", path);
    require_same(given.sampler, m.sampler, "--sampler", "orb:sampler", path);
    require_same(given.max_depth, m.max_depth, "--max-depth", "orb:maxDepth", path);
    plan.config.width = file.film.width;
    plan.config.height = file.film.height;
    plan.config.seed = m.seed;
    plan.config.mode = parse_mode(m.mode);
    plan.config.sampler = parse_sampler(m.sampler);
    plan.config.max_depth = m.max_depth;

    plan.target_spp = given.spp ? *given.spp : m.target_spp;
    if (given.sample_range) {
        // Finishing an interrupted slice: the file must hold the start of it.
        const SampleRange slice = *given.sample_range;
        const SampleRanges& held = file.film.sample_ranges;
        if (held.ranges().size() != 1 || held.first() != slice.first || held.end() > slice.end())
            throw InputError(path + ": holds the samples " + held.format() + ", not the start of --sample-range " +
                             o.sample_range_text + "; drop --sample-range to continue the file after its last sample");
        plan.target_spp = slice.count;
        plan.slice = true;
    }
    // Samples of other kernels are another render's: it starts again (from
    // the slice's first sample), with the file's settings.
    if (m.kernel != plan.kernel) {
        say(plan.messages, MessageKind::Warning,
            path + ": " + exr::another_kernel(m.kernel, plan.kernel) + "; rendering it again from its first sample");
        plan.first_sample = given.sample_range ? given.sample_range->first : 0;
        set_passes(plan, given.passes ? *given.passes : file.passes);
        plan.resumed = std::move(file);
        apply_adaptive(o, plan);
        plan.resumed.reset();
        return;
    }
    if (plan.target_spp < file.film.samples_per_pixel)
        throw InputError(path + ": already holds " + std::to_string(file.film.samples_per_pixel) +
                         " samples per pixel, more than the " + std::to_string(plan.target_spp) + " asked for");
    set_passes(plan, given.passes ? *given.passes : file.passes);
    plan.resumed = std::move(file);
    plan.resumed_path = path;
    apply_adaptive(o, plan);
    exr::require_resumable(*plan.resumed, plan.passes, path);
}

// pose_at's work (render_plan.h), whose errors pose_at names the frame in.
PosedFrame pose_scene_at(const RenderPlan& plan, long frame) {
    PosedFrame posed;
    posed.frame = frame;
    // A scene without animation is the same at every frame: the first
    // frame takes it (and its hash) and every other frame keeps it, unless
    // --orbit turns its camera. (For a changing scene only the imported
    // scene and the settings are read, which nothing changes while frames
    // render: safe on another thread.)
    if (!changes_per_frame(plan) && plan.frame) return posed;
    if (plan.trajectory) {
        // Frame 1 as the plan read and styled it, the first time it is posed.
        if (frame == 1 && plan.trajectory_first) posed.scene = plan.trajectory_first->take();
        if (!posed.scene) {
            posed.scene = trajectory_frame(*plan.trajectory, frame, plan.scene_label);
            // Quietly: this runs on the thread that reads the next frame while
            // one renders, and the range of frame 1 was said when the plan was made.
            apply_sphere_styling(*posed.scene, plan.style, plan.scene_label);
        }
    } else {
        posed.scene = pose_scene(plan.imported, frame_time(frame, plan.settings.fps), plan.scene_label);
    }
    apply_camera_request(*posed.scene, plan.settings, frame, plan.scene_label);
    posed.hash = scene_content_hash(*posed.scene);
    return posed;
}

// The host memory an image needs beside the renderer's: the film read back
// and its EXR encoding (the values, the exact sums where the image will
// carry them, the compressed blocks). A frame run holds several at once (the
// one rendering and BackgroundWriter's in flight).
std::uint64_t image_bytes(const RenderPlan& plan, const PlanOptions& o) {
    const auto pixels = static_cast<std::uint64_t>(plan.config.width) * static_cast<std::uint64_t>(plan.config.height);
    std::uint64_t film = 0;
    for (const film::ChannelInfo& info : film::kChannels)
        if ((plan.config.film_channels & film::channel_bit(info.channel)) != 0) film += film::pixel_bytes(info) * pixels;
    // Checkpoints, slices and renders that --time will stop short carry their exact sums (render_film.cpp).
    const bool exact_sums = !plan.half && (o.checkpoints_or_time_limit || plan.slice);
    return film + 2 * exr::encoding_bytes(plan.passes, exact_sums, pixels);
}

RenderPlan plan_render(const PlanOptions& o, SceneInput input, const render::DevelopmentKnobs& knobs);

}  // namespace

RenderPlan make_render_plan(const PlanOptions& o, SceneInput input, const render::DevelopmentKnobs& knobs) {
    RenderPlan plan = plan_render(o, std::move(input), knobs);
    const std::uint64_t image = image_bytes(plan, o);
    if (renders_frames(o)) plan.frames_in_flight = BackgroundWriter::frames_in_flight(image);
    plan.config.caller_host_bytes = (1 + plan.frames_in_flight) * image;
    // The denoiser's device starts, and its filter is set up for the
    // image's size, on a thread of their own while kernels build and
    // samples render.
    if (o.denoise && o.load_denoiser)
        plan.denoiser = std::make_shared<denoise::Denoiser>(
            denoise::DenoiseSettings{}, denoise::ImageSize{plan.config.width, plan.config.height});
    return plan;
}

namespace {

RenderPlan plan_render(const PlanOptions& o, SceneInput input, const render::DevelopmentKnobs& knobs) {
    RenderPlan plan;
    plan.messages = o.messages;
    plan.style = o.style;  // kept for the frames a trajectory reads later
    plan.trajectory = std::move(input.trajectory);
    plan.scene_label = std::move(input.label);
    Scene imported = std::move(input.imported);

    plan.config.device = o.device;
    plan.config.development = knobs;
    if (!o.kernel_dir.empty()) plan.config.development.kernel_dir = o.kernel_dir;  // the option wins over ORB_KERNEL_DIR
    plan.kernel = render::kernel_identity(plan.config.development);
    plan.config.use_binary_cache = !o.no_cache;
    // A build from source takes seconds (tens on a CPU): said once, whatever the devices and frames.
    plan.config.on_slow_kernel_build = [cached = !o.no_cache, said = std::make_shared<std::once_flag>(),
                                         messages = o.messages] {
        std::call_once(*said, [&] {
            say(messages, MessageKind::Info,
                cached ? "building kernels for this scene (once; cached)"
                       : "building kernels for this scene (--no-cache: every run builds them)");
        });
    };
    plan.half = o.given.half;
    if (o.compression) plan.compression = *o.compression;
    plan.denoise = o.denoise;

    if (!o.resume.empty()) {
        apply_resume(o, imported, plan);
        return plan;
    }
    // The render block (size, spp, depth) is not animated: any pose has the rest pose's.
    const RequestSettings& s = plan.settings = o.settings;
    plan.config.width = *s.width;
    plan.config.height = *s.height;
    plan.config.seed = s.seed;
    plan.config.mode = parse_mode(s.mode);
    plan.config.sampler = parse_sampler(s.sampler);
    plan.config.max_depth = *s.max_depth;
    plan.target_spp = *s.spp;
    plan.first_sample = s.first_sample;
    plan.slice = s.slice;
    set_passes(plan, s.passes);
    apply_adaptive(o, plan);
    if (renders_frames(o)) {
        plan.frames = o.frames;
        if (plan.trajectory) {
            // Frame f is the file's frame f: one past the end is an error before anything renders.
            require_trajectory_frames(*plan.trajectory, plan.frames, plan.scene_label);
            if (plan.trajectory->frame_count() == 1 && plan.frames.size() > 1 && !camera_moves(s))
                say(plan.messages, MessageKind::Warning,
                    plan.scene_label + ": holds one frame: every frame renders the same image");
            // Each frame is read from the file when it is posed; frame 1, read and styled already, is kept
            // for its pose (when it is one of the frames: else it would only hold memory).
            if (std::find(plan.frames.begin(), plan.frames.end(), 1L) != plan.frames.end())
                plan.trajectory_first = std::make_shared<HeldFrame>(std::move(imported));
            return plan;
        }
        for (const std::string& warning :
             frame_warnings(imported, plan.frames, s.fps, camera_moves(s), plan.scene_label))
            say(plan.messages, MessageKind::Warning, warning);
        plan.imported = std::move(imported);
        // Posed lazily: a run that finds every frame finished poses none.
        return plan;
    }
    if (plan.trajectory && o.time_at)
        throw InputError(plan.scene_label + ": --time-at poses an animated scene at a time; a trajectory's frames "
                         "are chosen by number: --frame N");
    if (plan.trajectory && plan.trajectory->frame_count() > 1)
        say(plan.messages, MessageKind::Info, plan.scene_label + ": rendering its first frame of " +
                  std::to_string(plan.trajectory->frame_count()) + " (--frame N or --frames 1-" +
                  std::to_string(plan.trajectory->frame_count()) + " renders the others)");
    plan.scene_time = o.time_at.value_or(0.0);
    plan.scene = pose_scene(std::move(imported), plan.scene_time, plan.scene_label);
    apply_camera_request(plan.scene, s, std::nullopt, plan.scene_label);
    plan.scene_hash = scene_content_hash(plan.scene);
    return plan;
}

}  // namespace

PosedFrame pose_at(const RenderPlan& plan, long frame) {
    return for_frame(frame, [&] { return pose_scene_at(plan, frame); });
}

void install(RenderPlan& plan, PosedFrame&& posed) {
    if (posed.scene) {
        plan.scene = std::move(*posed.scene);
        plan.scene_hash = std::move(posed.hash);
        plan.scene_changed = true;
        plan.prepared_scene = std::move(posed.prepared);
        // Without animation or orbit the pose is the scene itself, for good: its imported copy is not needed again.
        if (!changes_per_frame(plan)) plan.imported = Scene{};
    }
    plan.scene_time = frame_time(posed.frame, plan.settings.fps);
    plan.config.seed = plan.settings.seed_of(posed.frame);
    plan.frame = exr::FrameInfo{posed.frame, plan.settings.fps};
}

bool changes_per_frame(const RenderPlan& plan) {
    return !plan.imported.animation.empty() || (plan.trajectory && plan.trajectory->frame_count() > 1) ||
           camera_moves(plan.settings);
}

void pose_frame(RenderPlan& plan, long frame) { install(plan, pose_at(plan, frame)); }

bool posed_at(const RenderPlan& plan, long frame) { return plan.frame && plan.frame->number == frame; }

exr::RenderRequest request_for(RenderPlan& plan, std::optional<long> frame) {
    exr::RenderRequest request = plan.settings.request(frame, plan.scene_time);
    // --passes with the denoiser's guides, or adaptive sampling's variance and counts.
    if (plan.denoise || plan.adaptive.any()) request.passes = plan.passes;
    request.adaptive = exr::RenderRequest::Adaptive{plan.adaptive.noise_threshold, plan.adaptive.target_error};
    request.kernel = plan.kernel;
    request.scene = [&plan, frame] {
        if (frame && !posed_at(plan, *frame)) pose_frame(plan, *frame);
        return scene_identity(plan.scene, plan.scene_hash, plan.config.width, plan.config.height);
    };
    return request;
}

exr::ExrMetadata plan_metadata(const RenderPlan& plan) {
    exr::ExrMetadata m;
    m.target_spp = plan.target_spp;
    m.seed = plan.config.seed;
    m.max_depth = plan.config.max_depth;
    m.mode = device::name_in(device::kIntegratorModeNames, plan.config.mode);
    m.sampler = device::name_in(device::kSamplerNames, plan.config.sampler);
    m.scene_file = plan.scene_label;
    m.scene_hash = plan.scene_hash;
    m.kernel = plan.kernel;
    m.environment_seen = environment_emits(plan.scene.environment);
    m.scene_time = plan.scene_time;
    m.version = ORB_VERSION_STRING;  // the project's version, as orb::cli::version_string() says it
    m.world_to_camera = exr::world_to_camera(plan.scene.camera);
    m.world_to_ndc = exr::world_to_ndc(plan.scene.camera, plan.config.width, plan.config.height);
    if (plan.resumed) m.render_seconds = plan.resumed->metadata.render_seconds;
    m.frame = plan.frame;
    m.noise_threshold = plan.adaptive.noise_threshold;
    m.target_error = plan.adaptive.target_error;
    return m;
}

}  // namespace orb::job
