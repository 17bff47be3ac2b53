#include "film_output.h"

#include "interrupt.h"
#include "orb/cli/messages.h"
#include "progress_reporter.h"

namespace orb::render_cli {

job::FilmOutcome render_film(render::Renderer& renderer, const job::RenderPlan& plan, const RenderOptions& options,
                             job::ImageOutput& image, const std::string& label, job::FrameClaim* claim, Film reuse,
                             bool read_later) {
    ProgressReporter progress(cli::quiet(), static_cast<double>(renderer.pixel_count()),
                              options.time_limit.value_or(0), label, options.progress_interval);
    job::FilmRun run;
    run.time_limit = options.time_limit;
    run.checkpoint = options.checkpoint;
    run.cancel = &interrupt_requested();
    run.on_pass = [&](const render::ProgressState& state) {
        progress.on_pass(state);
        if (claim) claim->refresh();
    };
    run.on_checkpoint = [&](job::FinalImage& checkpoint, const render::ProgressState& state) {
        image.write(checkpoint.encode());
        progress.on_checkpoint(state, image.display_name());
    };
    run.reuse = std::move(reuse);
    run.read_later = read_later;
    job::FilmOutcome outcome = job::render_film(renderer, plan, std::move(run));
    progress.finish(outcome.final_state);
    outcome.stats.output = image.path();
    return outcome;
}

std::string film_summary(const job::FilmOutcome& outcome, const render::Renderer& renderer, const job::ImageOutput& image) {
    const SampleRanges& held = renderer.sample_ranges();
    const bool from_zero = held.ranges().size() == 1 && held.first() == 0;
    return std::to_string(outcome.stats.spp) + " spp" + (from_zero ? "" : " (samples " + held.format() + ")") +
           " in " + format_duration(outcome.stats.seconds) + " (" + format_rate(outcome.stats.samples_per_second) +
           ") -> " + image.display_name();
}

}  // namespace orb::render_cli
