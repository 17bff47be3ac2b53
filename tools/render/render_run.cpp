#include "render_run.h"

#include <cstdio>
#include <iostream>

#include "interrupt.h"
#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/cli/tool_main.h"
#include "orb/render/progressive.h"
#include "orb/scene/error.h"
#include "progress_reporter.h"
#include "run_stats.h"

namespace orb::render_cli {
namespace {

std::string device_label(const render::DeviceInfo& d) { return d.name + " (" + d.platform + ")"; }

const char* stop_reason_name(render::StopReason reason) {
    switch (reason) {
        case render::StopReason::ReachedSpp: return "spp";
        case render::StopReason::ReachedTime: return "time";
        case render::StopReason::Interrupted: return "interrupted";
    }
    return "?";
}

class ImageWriter {
public:
    ImageWriter(const RenderPlan& plan, cli::OutputFile& output, const render::Renderer& renderer)
        : output_(output), renderer_(renderer), metadata_(plan_metadata(plan)) {
        previous_seconds_ = metadata_.render_seconds;
        metadata_.device = device_label(renderer.device());
        options_.half = plan.half;
        options_.passes = plan.passes;
    }

    void write(double seconds_this_run) {
        const render::Film film = renderer_.read_film();
        metadata_.render_seconds = previous_seconds_ + seconds_this_run;
        output_.write(exr::encode_film_exr(film, metadata_, options_));
    }

private:
    cli::OutputFile& output_;
    const render::Renderer& renderer_;
    exr::ExrMetadata metadata_;
    exr::ExrWriteOptions options_;
    double previous_seconds_ = 0;
};

RunStats base_stats(const RenderPlan& plan, const render::Renderer& renderer) {
    RunStats stats;
    stats.device = renderer.device();
    stats.width = plan.config.width;
    stats.height = plan.config.height;
    stats.device_memory_bytes = renderer.device_memory_bytes();
    return stats;
}

}  // namespace

int run_render(const RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs) {
    render::Renderer renderer(plan.scene, plan.config);
    cli::info("device: " + device_label(renderer.device()));
    if (plan.resumed) {
        renderer.load_film(plan.resumed->film);
        cli::info("resuming " + options.resume + " at " + std::to_string(plan.resumed->film.samples_per_pixel) +
                  " spp (samples " + plan.resumed->film.sample_ranges.format() + ")");
    } else {
        renderer.clear(plan.first_sample);
    }
    const std::uint64_t start_spp = renderer.samples_per_pixel();

    ImageWriter writer(plan, *outputs.image, renderer);
    const double pixels = double(plan.config.width) * plan.config.height;
    ProgressReporter progress(cli::quiet(), pixels, options.time_limit.value_or(0));

    render::ProgressiveLimits limits;
    limits.target_spp = plan.target_spp;
    limits.max_seconds = options.time_limit.value_or(0);
    limits.checkpoint_seconds = options.checkpoint.value_or(0);
    render::ProgressiveCallbacks callbacks;
    callbacks.on_pass = [&](const render::ProgressState& state) { progress.on_pass(state); };
    callbacks.on_checkpoint = [&](const render::ProgressState& state) {
        // A checkpoint that cannot be written (a full disk, say) must not
        // cost the render; the final write reports for good if it persists.
        try {
            writer.write(state.elapsed_seconds);
            progress.on_checkpoint(state, options.output);
        } catch (const std::exception& e) {
            cli::warning(std::string("checkpoint not written: ") + e.what());
        }
    };

    // From here on SIGINT/SIGTERM end the render gracefully; before, during
    // the kernel build, there is nothing to save and they end it at once.
    install_interrupt_handlers();

    render::ProgressState final_state;
    const render::StopReason reason =
        render::render_progressively(renderer, limits, callbacks, interrupt_requested(), &final_state);
    progress.finish(final_state);

    if (renderer.samples_per_pixel() == 0) {
        cli::error("interrupted before the first pass finished; no image written");
        return interrupt_exit_code() ? interrupt_exit_code() : cli::kFailure;
    }
    writer.write(final_state.elapsed_seconds);

    RunStats stats = base_stats(plan, renderer);
    stats.spp = renderer.samples_per_pixel();
    stats.spp_this_run = stats.spp - start_spp;
    stats.passes = final_state.pass;
    stats.seconds = final_state.elapsed_seconds;
    stats.samples_per_second = final_state.samples_per_second;
    stats.stop_reason = stop_reason_name(reason);
    stats.output = options.output;
    stats.sample_ranges = renderer.sample_ranges().format();
    if (outputs.stats) outputs.stats->write(stats_json(stats));

    const render::SampleRanges& held = renderer.sample_ranges();
    const bool from_zero = held.ranges().size() == 1 && held.first() == 0;
    const std::string summary = std::to_string(stats.spp) + " spp" +
                                (from_zero ? "" : " (samples " + held.format() + ")") + " in " +
                                format_duration(stats.seconds) + " (" +
                                format_rate(stats.samples_per_second) + ") -> " +
                                outputs.image->display_name();
    if (reason == render::StopReason::Interrupted) {
        cli::warning("interrupted: wrote " + summary);
        return interrupt_exit_code() ? interrupt_exit_code() : cli::kFailure;
    }
    cli::info(std::string(reason == render::StopReason::ReachedTime ? "time limit reached: " : "done: ") + summary);
    return cli::kSuccess;
}

int run_benchmark(const RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs) {
    render::Renderer renderer(plan.scene, plan.config);
    cli::info("device: " + device_label(renderer.device()));
    const render::BenchmarkResult result = render::run_benchmark(renderer, options.benchmark_seconds);
    cli::info("benchmark: " + std::to_string(result.samples) + " samples in " + format_duration(result.seconds) +
              " over " + std::to_string(result.passes) + " passes at " + std::to_string(plan.config.width) + "x" +
              std::to_string(plan.config.height));

    if (outputs.stats) {
        RunStats stats = base_stats(plan, renderer);
        stats.spp = renderer.samples_per_pixel();
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
