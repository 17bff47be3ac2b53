#include "frame_jobs.h"

#include "interrupt.h"
#include "orb/cli/frame_spec.h"
#include "orb/cli/messages.h"
#include "render_film.h"

namespace orb::render_cli {

std::vector<Job> jobs_of(const RenderPlan& plan, const RenderOptions& options) {
    if (plan.frames.empty()) return {Job{std::nullopt, options.output}};
    // With --frame N a name without a frame-number field is taken as it is.
    const bool pattern = cli::count_frame_fields(options.output) > 0;
    std::vector<Job> jobs;
    for (long frame : plan.frames)
        jobs.push_back(
            {frame, pattern ? cli::expand_frame_pattern(options.output, static_cast<int>(frame)) : options.output});
    return jobs;
}

std::string label_of(const Job& job) { return job.frame ? "frame " + std::to_string(*job.frame) + ": " : ""; }

void pose_for(RenderPlan& plan, const Job& job) {
    if (job.frame && !posed_at(plan, *job.frame)) pose_frame(plan, *job.frame);
}

void upload_changed_scene(RenderPlan& plan, render::Renderer& renderer) {
    if (plan.scene_changed) {
        if (plan.prepared_scene)
            renderer.set_scene(std::move(*plan.prepared_scene));
        else
            renderer.set_scene(plan.scene);
    }
    plan.scene_changed = false;
    plan.prepared_scene.reset();
}

void set_up(RenderPlan& plan, const Job& job, std::optional<render::Renderer>& renderer) {
    pose_for(plan, job);
    if (!renderer) {
        renderer.emplace(plan.scene, plan.config);
        cli::info(devices_line(*renderer));
        // From here on a signal ends the frame in flight gracefully; before,
        // during the kernel build, there is nothing to save.
        install_interrupt_handlers();
        plan.scene_changed = false;  // the renderer was made with it
        plan.prepared_scene.reset();
    } else {
        upload_changed_scene(plan, *renderer);
        renderer->set_seed(plan.config.seed);
    }
    renderer->clear(plan.first_sample);
}

void PosePrefetch::start(const RenderPlan& plan, const Job& next, render::Renderer& renderer) {
    if (!next.frame || !changes_per_frame(plan)) return;
    frame_ = *next.frame;
    future_ = std::async(std::launch::async, [&plan, &renderer, frame = frame_] {
        PosedFrame posed = pose_at(plan, frame);
        if (posed.scene) posed.prepared = renderer.prepare_scene(*posed.scene);
        return posed;
    });
}

void PosePrefetch::use_for(RenderPlan& plan, const Job& job) {
    if (!future_.valid()) return;
    PosedFrame posed = future_.get();
    if (job.frame && *job.frame == frame_ && !posed_at(plan, frame_)) install(plan, std::move(posed));
}

}  // namespace orb::render_cli
