#include "render_run.h"

#include <cstdio>
#include <iostream>

#include "interrupt.h"
#include "orb/cli/messages.h"
#include "orb/cli/tool_main.h"
#include "orb/render/progressive.h"
#include "progress_reporter.h"
#include "render_film.h"
#include "run_stats.h"

namespace orb::render_cli {

int run_render(const RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs) {
    render::Renderer renderer(plan.scene, plan.config);
    cli::info(std::string(renderer.devices().size() > 1 ? "devices: " : "device: ") + devices_label(renderer));
    if (plan.resumed) {
        renderer.load_film(plan.resumed->film);
        cli::info("resuming " + options.resume + " at " + std::to_string(plan.resumed->film.samples_per_pixel) +
                  " spp (samples " + plan.resumed->film.sample_ranges.format() + ")");
    } else {
        renderer.clear(plan.first_sample);
    }

    // From here on SIGINT/SIGTERM end the render gracefully; before, during
    // the kernel build, there is nothing to save and they end it at once.
    install_interrupt_handlers();

    const FilmOutcome outcome = render_film(renderer, plan, options, *outputs.image, "", nullptr);
    if (!outcome.rendered) {
        cli::error("interrupted before the first pass finished; no image written");
        return interrupt_exit_code() ? interrupt_exit_code() : cli::kFailure;
    }
    outputs.image->write(outcome.image.encode());
    if (outputs.stats) outputs.stats->write(stats_json(outcome.stats));

    const std::string summary = film_summary(outcome, renderer, *outputs.image);
    if (outcome.reason == render::StopReason::Interrupted) {
        cli::warning("interrupted: wrote " + summary);
        return interrupt_exit_code() ? interrupt_exit_code() : cli::kFailure;
    }
    cli::info(std::string(outcome.reason == render::StopReason::ReachedTime ? "time limit reached: " : "done: ") +
              summary);
    return cli::kSuccess;
}

int run_benchmark(const RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs) {
    render::Renderer renderer(plan.scene, plan.config);
    cli::info(std::string(renderer.devices().size() > 1 ? "devices: " : "device: ") + devices_label(renderer));
    const render::BenchmarkResult result = render::run_benchmark(renderer, options.benchmark_seconds);
    cli::info("benchmark: " + std::to_string(result.samples) + " samples in " + format_duration(result.seconds) +
              " over " + std::to_string(result.passes) + " passes at " + std::to_string(plan.config.width) + "x" +
              std::to_string(plan.config.height));

    if (outputs.stats) {
        RunStats stats = renderer_stats(renderer);
        stats.spp_this_run = stats.spp;
        stats.passes = result.passes;
        stats.seconds = result.seconds;
        stats.samples_per_second = result.samples_per_second;
        stats.stop_reason = "benchmark";
        outputs.stats->write(stats_json(stats));
    }
    std::printf("samples_per_second=%.0f\n", result.samples_per_second);
    std::fflush(stdout);
    return cli::kSuccess;
}

}  // namespace orb::render_cli
