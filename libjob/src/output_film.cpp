#include "orb/job/output_film.h"

#include "orb/exr/film_exr.h"

namespace orb::job {

void start_film(const RenderPlan& plan, render::Renderer& renderer) {
    if (!plan.resumed) {
        renderer.clear(plan.first_sample);
        return;
    }
    const Film& film = plan.resumed->film;
    renderer.load_film(film);
    say(plan.messages, MessageKind::Info,
        "resuming " + plan.resumed_path + " at " + std::to_string(film.samples_per_pixel) + " spp (samples " +
            film.sample_ranges.format() + ")");
    if (!plan.resumed->exact) say(plan.messages, MessageKind::Warning, plan.resumed_path + ": " + exr::kMeansOnly);
}

FilmOutcome render_into(render::Renderer& renderer, const RenderPlan& plan, const OutputRun& run, ImageOutput& output,
                        const std::string& label, FrameClaim* claim, Film reuse, bool read_later) {
    // Told of the film before its first pass, so that its time starts with the film's.
    FilmProgress* progress = run.progress;
    if (progress) progress->start(label, static_cast<double>(renderer.pixel_count()));
    FilmRun film;
    film.time_limit = run.time_limit;
    film.checkpoint = run.checkpoint;
    film.cancel = run.cancel;
    film.on_pass = [&](const render::ProgressState& state) {
        if (progress) progress->on_pass(state);
        // A claim not refreshed for a while is taken over by another host.
        if (claim) claim->refresh();
    };
    film.on_checkpoint = [&](FinalImage& checkpoint, const render::ProgressState& state) {
        output.write(checkpoint.encode());
        if (progress) progress->on_checkpoint(state, output.display_name());
    };
    film.reuse = std::move(reuse);
    film.read_later = read_later;
    FilmOutcome outcome = render_film(renderer, plan, std::move(film));
    if (progress) progress->finish(outcome.final_state);
    outcome.stats.output = output.path();
    return outcome;
}

RunStats written_stats(const FilmOutcome& outcome, double setup_seconds) {
    RunStats stats = outcome.stats;
    stats.setup_seconds = setup_seconds;
    if (outcome.image.denoise_times) stats.denoise = *outcome.image.denoise_times;
    return stats;
}

}  // namespace orb::job
