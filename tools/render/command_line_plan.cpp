#include "command_line_plan.h"

#include "interrupt.h"
#include "orb/cli/legend_output.h"
#include "orb/cli/messages.h"
#include "orb/job/scene_pose.h"
#include "orb/request/scene_input.h"

namespace orb::render_cli {
namespace {

job::PlanOptions plan_options(const RenderOptions& o, const Scene& imported) {
    job::PlanOptions plan;
    plan.given = request::given_settings(o);
    plan.sample_range_text = o.sample_range.value_or("");
    plan.time_at = o.time_at;
    if (o.resume.empty()) {
        // The render block (size, spp, depth) is not animated: any pose has the rest pose's.
        plan.settings = request::resolve_request(o, &imported.render, o.frames ? &*o.frames : nullptr, renders_frames(o));
    } else {
        plan.resume_camera = request::camera_request(o.camera);  // --orbit needs frames, which --resume excludes
    }
    if (renders_frames(o)) plan.frames = o.frame ? std::vector<long>{*o.frame} : parse_frames_option(*o.frames);
    plan.resume = o.resume;
    plan.noise_threshold = o.noise_threshold;
    plan.target_error = o.target_error;
    plan.device = o.device;
    plan.kernel_dir = o.kernel_dir;
    plan.no_cache = o.no_cache;
    if (o.compression) plan.compression = exr::parse_compression(*o.compression);
    plan.denoise = o.denoise;
    plan.load_denoiser = !o.missing;
    plan.checkpoints_or_time_limit = o.checkpoint.has_value() || o.time_limit.has_value();
    plan.messages = command_line_messages();
    return plan;
}

}  // namespace

job::MessageSink command_line_messages() {
    return [](job::MessageKind kind, const std::string& message) {
        switch (kind) {
            case job::MessageKind::Info: cli::info(message); break;
            case job::MessageKind::Warning: cli::warning(message); break;
            case job::MessageKind::Error: cli::error(message); break;
        }
    };
}

job::OutputRun output_run(const RenderOptions& o, job::FilmProgress& progress) {
    return {o.time_limit, o.checkpoint, &interrupt_requested(), &progress};
}

job::RenderPlan make_render_plan(const RenderOptions& o, const render::DevelopmentKnobs& knobs) {
    // Usage errors before the scene is read; kept for the frames a trajectory reads later.
    const SphereStyleOptions style = cli::sphere_style_options(o.style);
    std::optional<cli::LegendOutput> legend = cli::LegendOutput::prepare(o.style, {{"SCENE", o.scene}});
    job::SceneInput input = request::read_scene_input(o.scene, o.reading);
    // Before the hash: a styled scene is another scene (its outputs say so, and --resume checks it).
    const auto style_scene = [&] { return cli::apply_sphere_style(input.imported, style, input.label); };
    const SphereStyleResult styled = input.trajectory ? job::for_frame(1, style_scene) : style_scene();
    if (legend)
        legend->write(styled, input.label,
                      input.trajectory && input.trajectory->frame_count() > 1 && !style.color_range);
    job::PlanOptions options = plan_options(o, input.imported);
    options.style = style;
    return job::make_render_plan(options, std::move(input), knobs);
}

}  // namespace orb::render_cli
