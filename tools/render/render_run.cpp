#include "render_run.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include "interrupt.h"
#include "orb/cli/messages.h"
#include "orb/cli/tool_main.h"
#include "orb/render/progressive.h"
#include "progress_reporter.h"
#include "render_film.h"
#include "run_stats.h"

namespace orb::render_cli {
namespace {

// The renderer for `plan`, and the seconds from reading the scene until it
// could render: a million spheres take seconds before the first pass, and
// the line below says where they went.
struct ReadyRenderer {
    std::unique_ptr<render::Renderer> renderer;
    double setup_seconds = 0;
};

ReadyRenderer make_ready_renderer(const RenderPlan& plan) {
    const auto began = std::chrono::steady_clock::now();
    ReadyRenderer ready{std::make_unique<render::Renderer>(plan.scene, plan.config), 0};
    const double construct = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    ready.setup_seconds = plan.read_seconds + construct;
    const render::Renderer& r = *ready.renderer;
    cli::info(devices_line(r));
    const render::Renderer::TreeReport tree = r.tree_report();
    const std::string spheres = std::to_string(plan.scene.spheres.size()) + " spheres";
    cli::info("ready in " + format_duration(ready.setup_seconds) + ": scene read and hashed in " +
              format_duration(plan.read_seconds) + ", " +
              (tree.nodes ? "BVH of " + std::to_string(tree.nodes) + " nodes over " + spheres + " built in " +
                                format_duration(tree.seconds)
                          : spheres + ", no BVH") +
              ", kernels and upload " + format_duration(construct - tree.seconds));
    return ready;
}

}  // namespace

int run_render(const RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs) {
    const ReadyRenderer ready = make_ready_renderer(plan);
    render::Renderer& renderer = *ready.renderer;
    if (plan.resumed) {
        renderer.load_film(plan.resumed->film);
        cli::info("resuming " + options.resume + " at " + std::to_string(plan.resumed->film.samples_per_pixel) +
                  " spp (samples " + plan.resumed->film.sample_ranges.format() + ")");
        if (!plan.resumed->exact) cli::warning(options.resume + ": " + exr::kMeansOnly);
    } else {
        renderer.clear(plan.first_sample);
    }

    // From here on SIGINT/SIGTERM end the render gracefully; before, during
    // the kernel build, there is nothing to save and they end it at once.
    install_interrupt_handlers();

    FilmOutcome outcome = render_film(renderer, plan, options, *outputs.image, "", nullptr);
    if (!outcome.rendered) {
        cli::error("interrupted before the first pass finished; no image written");
        return interrupt_exit_code() ? interrupt_exit_code() : cli::kFailure;
    }
    outputs.image->write(outcome.image.encode());
    if (outputs.stats) {
        RunStats stats = outcome.stats;
        stats.setup_seconds = ready.setup_seconds;
        if (outcome.image.denoise_times) stats.denoise = *outcome.image.denoise_times;
        outputs.stats->write(stats_json(stats));
    }

    const std::string summary = film_summary(outcome, renderer, *outputs.image);
    if (outcome.reason == render::StopReason::Interrupted) {
        cli::warning("interrupted: wrote " + summary);
        return interrupt_exit_code() ? interrupt_exit_code() : cli::kFailure;
    }
    const char* how = outcome.reason == render::StopReason::ReachedTime    ? "time limit reached: "
                      : outcome.reason == render::StopReason::Converged ? "every pixel below --noise-threshold: "
                      : outcome.reason == render::StopReason::ReachedError ? "--target-error reached: "
                                                                           : "done: ";
    cli::info(how + summary);
    return cli::kSuccess;
}

int run_benchmark(const RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs) {
    const ReadyRenderer ready = make_ready_renderer(plan);
    render::Renderer& renderer = *ready.renderer;
    const render::BenchmarkResult result = render::run_benchmark(renderer, options.benchmark_seconds);
    cli::info("benchmark: " + std::to_string(result.samples) + " samples in " + format_duration(result.seconds) +
              " over " + std::to_string(result.passes) + " passes at " + std::to_string(plan.config.width) + "x" +
              std::to_string(plan.config.height));

    if (outputs.stats) {
        RunStats stats = renderer_stats(renderer);
        stats.spp_this_run = stats.spp;
        stats.samples_this_run = stats.samples;
        stats.passes = result.passes;
        stats.seconds = result.seconds;
        stats.samples_per_second = result.samples_per_second;
        stats.stop_reason = "benchmark";
        stats.setup_seconds = ready.setup_seconds;
        outputs.stats->write(stats_json(stats));
    }
    std::printf("samples_per_second=%.0f\n", result.samples_per_second);
    std::fflush(stdout);
    return cli::kSuccess;
}

}  // namespace orb::render_cli
