#include "orb/job/frame_run.h"

#include <algorithm>

#include "orb/exr/render_request.h"
#include "orb/job/background_writer.h"

namespace orb::job {
namespace {

// The one line saying what happens to an output that is there but is not
// the finished render asked for.
void announce(const MessageSink& messages, const std::string& label, const std::string& output,
              const exr::OutputJudgement& verdict) {
    if (verdict.state == exr::OutputState::Continuable)
        say(messages, MessageKind::Info, label + output + ": " + verdict.reason + ": continuing it");
    else if (verdict.state == exr::OutputState::Different)
        say(messages, MessageKind::Info, label + output + ": " + verdict.reason + ": rendering again");
}

}  // namespace

FramesRun run_frames(RenderPlan& plan, const std::vector<Job>& jobs, const FrameRunOptions& options,
                     const FrameRunHooks& hooks) {
    const bool finish_existing = options.skip_existing || options.claim;
    FramesRun run;
    std::optional<render::Renderer> renderer;
    BackgroundWriter writer(plan.messages, std::max<std::size_t>(1, plan.frames_in_flight));  // after the renderer: destroyed first, so a pending write ends before it
    std::vector<std::shared_ptr<denoise::DenoiseTimes>> denoise_times;  // each rendered frame's, known once its write is done
    PosePrefetch prefetch;
    const auto stop_requested = [&] { return options.film.cancel && options.film.cancel->load(); };
    const auto finish = [&] {
        writer.finish();
        for (std::size_t i = 0; i < run.rendered.size(); ++i)
            if (denoise_times[i]) run.rendered[i].denoise = *denoise_times[i];
        if (renderer) run.kernel_builds = renderer->programs_built();
        return run;
    };
    for (std::size_t index = 0; index < jobs.size(); ++index) {
        const Job& job = jobs[index];
        if (stop_requested()) break;
        prefetch.use_for(plan, job);
        const std::string label = label_of(job);
        std::optional<exr::OutputJudgement> verdict;
        const auto finished = [&] {
            if (verdict->state != exr::OutputState::Finished) return false;
            say(plan.messages, MessageKind::Info,
                label + job.output + ": finished (" + std::to_string(verdict->held_spp) + " spp); skipped");
            if (job.frame) run.skipped.push_back(*job.frame);
            if (hooks.skipped) hooks.skipped(job);
            return true;
        };
        if (finish_existing) {
            verdict = judge(plan, job);
            if (finished()) continue;
        }
        std::optional<FrameClaim> claim;
        if (options.claim) {
            std::string holder;
            claim = FrameClaim::acquire(job.output, options.claim_stale_after, holder);
            if (!claim) {
                say(plan.messages, MessageKind::Info, label + job.output + " is claimed by " + holder + "; skipped");
                ++run.claimed_elsewhere;
                continue;
            }
            // Another machine may have finished or continued it between the check and the claim.
            verdict = judge(plan, job);
            if (finished()) continue;
        }
        if (verdict) announce(plan.messages, label, job.output, *verdict);

        std::unique_ptr<ImageOutput> output = hooks.prepare_output(job);
        set_up(plan, job, renderer, hooks.renderer_made);
        plan.resumed.reset();
        if (verdict && verdict->state == exr::OutputState::Continuable &&
            continue_from(plan, label, job.output, *renderer))
            ++run.continued;
        if (index + 1 < jobs.size()) prefetch.start(plan, jobs[index + 1], *renderer);
        FilmOutcome outcome = render_into(*renderer, plan, options.film, *output, label, claim ? &*claim : nullptr,
                                          writer.take_spare_film(), /*read_later=*/true);
        if (!outcome.rendered) {
            run.stopped_before_image = label;
            return finish();
        }
        run.rendered.push_back(outcome.stats);
        denoise_times.push_back(outcome.image.denoise_times);
        const bool interrupted = outcome.reason == render::StopReason::Interrupted;
        const std::string written = written_line(outcome.reason, hooks.summary(outcome, *renderer, *output), false);
        // Written while the next frame renders, which says so once its file
        // is in place; a failed write ends the run at the next frame.
        writer.submit({std::move(outcome.image), std::move(output), std::move(claim), label, written, interrupted});
        if (interrupted) break;
    }
    return finish();
}

std::string frames_run_stats_json(const RenderPlan& plan, const FramesRun& run) {
    if (plan.frames.size() > 1 || run.rendered.empty()) return frames_stats_json(run.rendered, run.skipped);
    return stats_json(run.rendered.front());
}

}  // namespace orb::job
