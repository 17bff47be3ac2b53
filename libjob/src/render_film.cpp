#include "orb/job/render_film.h"

#include "orb/exr/film_exr.h"

namespace orb::job {
namespace {

class ImageWriter {
public:
    ImageWriter(const RenderPlan& plan, const render::Renderer& renderer)
        : renderer_(renderer), metadata_(plan_metadata(plan)), messages_(plan.messages) {
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
        image.messages = messages_;
        image.options.exact_sums = keeps_exact_sums(finished);
        if (read_later)
            image.arriving = renderer_.read_film_later();
        else
            renderer_.read_film(image.film);
        image.metadata.render_seconds = previous_seconds_ + seconds_this_run;
        return image;
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
        return !holds_samples_from_zero(renderer_.sample_ranges());
    }

    const render::Renderer& renderer_;
    exr::ExrMetadata metadata_;
    MessageSink messages_;
    exr::ExrWriteOptions options_;
    double previous_seconds_ = 0;
    bool slice_ = false;
};

}  // namespace

std::vector<exr::PostLayerPlanes> denoised_layer(const std::shared_ptr<denoise::Denoiser>& denoiser,
                                                 const std::shared_ptr<denoise::DenoiseTimes>& times) {
    if (!denoiser) return {};
    return {denoise::denoised_post_layer(*denoiser, "the rendered image", times)};
}

void FinalImage::warn_of_sums_out_of_range() const {
    const std::string label = metadata.frame ? "frame " + std::to_string(metadata.frame->number) + ": " : "";
    for (const film::OutOfRange& out : film::sums_out_of_range(film))
        say(messages, MessageKind::Warning, label + film::describe(out, film.width));
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

bool holds_samples_from_zero(const SampleRanges& held) { return held.ranges().size() == 1 && held.first() == 0; }

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

std::string written_line(render::StopReason reason, const std::string& summary, bool still) {
    switch (reason) {
        case render::StopReason::Interrupted: return "interrupted: wrote " + summary;
        case render::StopReason::ReachedTime: return "time limit reached: " + summary;
        case render::StopReason::Converged:
            return (still ? "every pixel below --noise-threshold: " : "done: ") + summary;
        case render::StopReason::ReachedError: return (still ? "--target-error reached: " : "done: ") + summary;
        case render::StopReason::ReachedSpp: break;
    }
    return "done: " + summary;
}

FilmOutcome render_film(render::Renderer& renderer, const RenderPlan& plan, FilmRun run) {
    // The denoiser's device, starting beside the kernels' build, warms up
    // before the first pass rather than during it (denoiser.h).
    if (plan.denoiser) plan.denoiser->wait_until_ready();
    const std::uint64_t start_spp = renderer.samples_per_pixel();
    const std::uint64_t start_samples = renderer.pixel_samples();
    ImageWriter writer(plan, renderer);

    render::ProgressiveLimits limits;
    limits.target_spp = plan.target_spp;
    limits.max_seconds = run.time_limit.value_or(0);
    limits.checkpoint_seconds = run.checkpoint.value_or(0);
    limits.checkpoint_passes = run.checkpoint_passes;
    std::optional<render::AdaptiveSampler> adaptive;
    if (plan.adaptive.any()) {
        adaptive.emplace(renderer, plan.adaptive,
                         plan.resumed ? plan.resumed->metadata.noise_threshold : std::optional<double>{});
        limits.gate = &*adaptive;
    }
    render::ProgressiveCallbacks callbacks;
    callbacks.on_pass = [&](const render::ProgressState& state) {
        if (run.on_pass) run.on_pass(state);
    };
    callbacks.on_checkpoint = [&](const render::ProgressState& state) {
        try {
            FinalImage checkpoint = writer.image(state.elapsed_seconds, false);
            checkpoint.checkpoint = true;
            if (run.on_checkpoint) run.on_checkpoint(checkpoint, state);
        } catch (const std::exception& e) {
            say(plan.messages, MessageKind::Warning, std::string("checkpoint not written: ") + e.what());
        }
    };

    FilmOutcome outcome;
    static const std::atomic<bool> never{false};
    outcome.rendering_began = std::chrono::steady_clock::now();
    outcome.reason = render::render_progressively(renderer, limits, callbacks, run.cancel ? *run.cancel : never,
                                                  &outcome.final_state);
    const render::ProgressState& final_state = outcome.final_state;
    if (renderer.samples_per_pixel() == 0) return outcome;
    const bool finished = outcome.reason != render::StopReason::Interrupted &&
                          outcome.reason != render::StopReason::ReachedTime;
    outcome.image = writer.image(final_state.elapsed_seconds, finished, std::move(run.reuse), run.read_later);
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
    stats.sample_ranges = renderer.sample_ranges().format();
    if (plan.frame) stats.frame = plan.frame->number;
    return outcome;
}

}  // namespace orb::job
