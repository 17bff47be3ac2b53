#include "render_run.h"

#include <chrono>
#include <cstdio>
#include <memory>

#include "command_line_plan.h"
#include "interrupt.h"
#include "orb/cli/messages.h"
#include "orb/cli/process_start.h"
#include "orb/cli/tool_main.h"
#include "orb/job/benchmarks.h"
#include "orb/job/output_film.h"
#include "progress_reporter.h"
#include "render_frames.h"

namespace orb::render_cli {
namespace {

// The renderer for `plan`, said as it is ready: a million spheres take
// seconds before the first pass, and the line says where they went.
job::ReadyRenderer said_ready_renderer(const job::RenderPlan& plan) {
    job::ReadyRenderer ready = job::make_ready_renderer(plan);
    const render::Renderer& r = *ready.renderer;
    cli::info(job::devices_line(r));
    const render::Renderer::TreeReport tree = r.tree_report();
    const std::string spheres = std::to_string(plan.scene.spheres.size()) + " spheres";
    cli::info("ready in " + format_duration(ready.setup_seconds) + ": scene read and hashed in " +
              format_duration(plan.read_seconds) + ", " +
              (tree.nodes ? "BVH of " + std::to_string(tree.nodes) + " nodes over " + spheres + " built in " +
                                format_duration(tree.seconds)
                          : spheres + ", no BVH") +
              ", kernels and upload " + format_duration(ready.construct_seconds - tree.seconds));
    return ready;
}

}  // namespace

int run_render(const job::RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs) {
    const job::ReadyRenderer ready = said_ready_renderer(plan);
    render::Renderer& renderer = *ready.renderer;
    job::start_film(plan, renderer);
    // From here on SIGINT/SIGTERM end the render gracefully; before, during
    // the kernel build, there is nothing to save and they end it at once.
    install_interrupt_handlers();

    OutputFileImage image(std::move(*outputs.image));
    ProgressReporter progress(cli::quiet(), options.time_limit.value_or(0), options.progress_interval);
    job::FilmOutcome outcome = job::render_into(renderer, plan, output_run(options, progress), image);
    if (!outcome.rendered) {
        cli::error("interrupted before the first pass finished; no image written");
        return stopped_exit_code();
    }
    image.write(outcome.image.encode());
    if (outputs.stats) {
        job::RunStats stats = job::written_stats(outcome, ready.setup_seconds);
        if (const auto started = cli::process_start())
            stats.startup_seconds = std::chrono::duration<double>(outcome.rendering_began - *started).count();
        outputs.stats->write(job::stats_json(stats));
    }

    const std::string written = job::written_line(outcome.reason, film_summary(outcome, renderer, image), true);
    if (outcome.reason == render::StopReason::Interrupted) {
        cli::warning(written);
        return stopped_exit_code();
    }
    cli::info(written);
    return cli::kSuccess;
}

int run_benchmark(const job::RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs) {
    const job::StillBenchmark bench = job::run_still_benchmark(said_ready_renderer(plan), options.benchmark_seconds);
    const render::BenchmarkResult& result = bench.result;
    cli::info("benchmark: " + std::to_string(result.samples) + " samples in " + format_duration(result.seconds) +
              " over " + std::to_string(result.passes) + " passes at " + std::to_string(plan.config.width) + "x" +
              std::to_string(plan.config.height));
    if (outputs.stats) outputs.stats->write(job::stats_json(bench.stats));
    std::printf("samples_per_second=%.0f\n", result.samples_per_second);
    std::fflush(stdout);
    return cli::kSuccess;
}

int run_frames_benchmark(job::RenderPlan& plan, const RenderOptions& options) {
    // Samples per frame: --spp, else 1.
    const job::FramesBenchmark bench = job::run_frames_benchmark(
        plan, jobs_of(plan, options), static_cast<int>(options.spp.value_or(1)),
        [](const std::string& path) { return std::make_unique<OutputFileImage>(cli::OutputFile(path, "-o")); },
        on_frames_renderer);
    char text[96];
    std::snprintf(text, sizeof text, " then the last writes %.1f ms; the loop %.1f ms a frame;", bench.last_writes_ms,
                  bench.loop_ms);
    cli::info("frames benchmark: " + std::to_string(bench.frames) + " frames at " + std::to_string(plan.config.width) +
              "x" + std::to_string(plan.config.height) + ", layers " + exr::format_passes(plan.passes) +
              (plan.half ? " (half)" : "") + ", " + exr::compression_name(plan.compression) + " " +
              std::to_string(bench.bytes_per_frame / 1000) + " kB a frame, " +
              job::kernel_builds_text(bench.kernel_builds) + ", " + std::to_string(bench.in_flight) +
              " frames written at once; per frame, mean (max) ms:" + job::FramesBenchmark::format(bench.loop) + text);
    cli::info("frames benchmark: one frame written alone, mean (max) ms:" + job::FramesBenchmark::format(bench.alone));
    cli::info("frames benchmark: the writer alone, " + std::to_string(bench.writer_frames) +
              " frames, ms a frame with N frames written at once (N: ms): " + bench.writer_pace_text());
    // The time a frame adds to the render path besides its samples.
    std::printf("frame_overhead_ms=%.1f\n", bench.overhead_ms);
    std::fflush(stdout);
    return cli::kSuccess;
}

}  // namespace orb::render_cli
