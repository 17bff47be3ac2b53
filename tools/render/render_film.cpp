#include "render_film.h"

#include "interrupt.h"
#include "orb/cli/messages.h"
#include "orb/exr/film_exr.h"
#include "progress_reporter.h"

namespace orb::render_cli {
namespace {

class ImageWriter {
public:
    ImageWriter(const RenderPlan& plan, cli::OutputFile& output, const render::Renderer& renderer)
        : output_(output), renderer_(renderer), metadata_(plan_metadata(plan)) {
        previous_seconds_ = metadata_.render_seconds;
        metadata_.device = devices_label(renderer);
        options_.half = plan.half;
        options_.passes = plan.passes;
        options_.compression = plan.compression;
        slice_ = plan.slice;
    }

    // `finished`: the render reached its end (not stopped by a signal or
    // --time), which decides whether the image keeps its exact sums.
    FinalImage image(double seconds_this_run, bool finished, Film reuse = {}, bool read_later = false) {
        FinalImage image{std::move(reuse), metadata_, options_, std::nullopt};
        image.options.exact_sums = keeps_exact_sums(finished);
        if (read_later)
            image.arriving = renderer_.read_film_later();
        else
            renderer_.read_film(image.film);
        image.metadata.render_seconds = previous_seconds_ + seconds_this_run;
        return image;
    }
    void write(double seconds_this_run) {
        FinalImage checkpoint = image(seconds_this_run, false);
        checkpoint.checkpoint = true;
        output_.write(checkpoint.encode());
    }

private:
    // Every image that may be continued or merged carries the film's exact
    // sums, so that doing so is bit for bit (docs/orb-render.md, "Exact
    // sums"): checkpoints, renders stopped short, slices. A finished render
    // of the samples [0, target) does not: they would triple a beauty
    // file's size and double its encoding time, frame after frame
    // (docs/design/exact-film-sums.md). HALF files never do (they are not
    // continued).
    bool keeps_exact_sums(bool finished) const {
        if (options_.half) return false;
        if (!finished || slice_) return true;
        const SampleRanges& held = renderer_.sample_ranges();
        return !(held.ranges().size() == 1 && held.first() == 0);
    }

    cli::OutputFile& output_;
    const render::Renderer& renderer_;
    exr::ExrMetadata metadata_;
    exr::ExrWriteOptions options_;
    double previous_seconds_ = 0;
    bool slice_ = false;
};

}  // namespace

void FinalImage::warn_of_sums_out_of_range() const {
    const std::string label = metadata.frame ? "frame " + std::to_string(metadata.frame->number) + ": " : "";
    for (const film::OutOfRange& out : film::sums_out_of_range(film))
        cli::warning(label + film::describe(out, film.width));
}

std::string device_label(const render::DeviceInfo& d) { return d.name + " (" + d.platform + ")"; }

std::string devices_label(const render::Renderer& renderer) {
    std::string text;
    for (const render::DeviceInfo& device : renderer.devices()) text += (text.empty() ? "" : "; ") + device_label(device);
    return text;
}

std::string devices_line(const render::Renderer& renderer) {
    return std::string(renderer.devices().size() > 1 ? "devices: " : "device: ") + devices_label(renderer);
}

std::string kernel_builds_text(int builds) {
    return std::to_string(builds) + (builds == 1 ? " kernel build" : " kernel builds");
}

const char* stop_reason_name(render::StopReason reason) {
    switch (reason) {
        case render::StopReason::ReachedSpp: return "spp";
        case render::StopReason::ReachedTime: return "time";
        case render::StopReason::Interrupted: return "interrupted";
        case render::StopReason::Converged: return "noise";
        case render::StopReason::ReachedError: return "error";
    }
    return "?";
}

FilmOutcome render_film(render::Renderer& renderer, const RenderPlan& plan, const RenderOptions& options,
                        cli::OutputFile& image, const std::string& label, FrameClaim* claim, Film reuse,
                        bool read_later) {
    const std::uint64_t start_spp = renderer.samples_per_pixel();
    const std::uint64_t start_samples = renderer.pixel_samples();
    ImageWriter writer(plan, image, renderer);
    ProgressReporter progress(cli::quiet(), static_cast<double>(renderer.pixel_count()),
                              options.time_limit.value_or(0), label, options.progress_interval);

    render::ProgressiveLimits limits;
    limits.target_spp = plan.target_spp;
    limits.max_seconds = options.time_limit.value_or(0);
    limits.checkpoint_seconds = options.checkpoint.value_or(0);
    std::optional<render::AdaptiveSampler> adaptive;
    if (plan.adaptive.any()) {
        adaptive.emplace(renderer, plan.adaptive,
                         plan.resumed ? plan.resumed->metadata.noise_threshold : std::optional<double>{});
        limits.gate = &*adaptive;
    }
    render::ProgressiveCallbacks callbacks;
    callbacks.on_pass = [&](const render::ProgressState& state) {
        progress.on_pass(state);
        if (claim) claim->refresh();
    };
    callbacks.on_checkpoint = [&](const render::ProgressState& state) {
        // A checkpoint that cannot be written (a full disk, say) must not
        // cost the render; the final write reports for good if it persists.
        try {
            writer.write(state.elapsed_seconds);
            progress.on_checkpoint(state, image.display_name());
        } catch (const std::exception& e) {
            cli::warning(std::string("checkpoint not written: ") + e.what());
        }
    };

    FilmOutcome outcome;
    render::ProgressState final_state;
    outcome.reason = render::render_progressively(renderer, limits, callbacks, interrupt_requested(), &final_state);
    progress.finish(final_state);
    if (renderer.samples_per_pixel() == 0) return outcome;
    const bool finished = outcome.reason != render::StopReason::Interrupted &&
                          outcome.reason != render::StopReason::ReachedTime;
    outcome.image = writer.image(final_state.elapsed_seconds, finished, std::move(reuse), read_later);
    outcome.image.denoiser = plan.denoiser;
    if (plan.denoiser) outcome.image.denoise_times = std::make_shared<denoise::DenoiseTimes>();
    // Ended on its adaptive rule: finished, though short of orb:targetSpp (render_request.h).
    if (outcome.reason == render::StopReason::Converged) outcome.image.metadata.adaptive_stop = exr::AdaptiveStop::Noise;
    if (outcome.reason == render::StopReason::ReachedError) outcome.image.metadata.adaptive_stop = exr::AdaptiveStop::Error;
    outcome.rendered = true;

    outcome.stats = renderer_stats(renderer);
    RunStats& stats = outcome.stats;
    stats.spp_this_run = stats.spp - start_spp;
    stats.samples_this_run = stats.samples - start_samples;
    if (adaptive) {
        stats.estimated_relmse = adaptive->estimated_relmse();
        stats.active_pixels = adaptive->active_pixel_count();
        stats.decisions = adaptive->decisions();
        stats.decision_seconds = adaptive->decision_seconds();
    }
    stats.passes = final_state.pass;
    stats.seconds = final_state.elapsed_seconds;
    stats.samples_per_second = final_state.samples_per_second;
    stats.stop_reason = stop_reason_name(outcome.reason);
    stats.output = image.path();
    stats.sample_ranges = renderer.sample_ranges().format();
    if (plan.frame) stats.frame = plan.frame->number;
    return outcome;
}

std::string film_summary(const FilmOutcome& outcome, const render::Renderer& renderer, const cli::OutputFile& image) {
    const SampleRanges& held = renderer.sample_ranges();
    const bool from_zero = held.ranges().size() == 1 && held.first() == 0;
    return std::to_string(outcome.stats.spp) + " spp" + (from_zero ? "" : " (samples " + held.format() + ")") +
           " in " + format_duration(outcome.stats.seconds) + " (" + format_rate(outcome.stats.samples_per_second) +
           ") -> " + image.display_name();
}

}  // namespace orb::render_cli
