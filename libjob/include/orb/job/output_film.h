// One film rendered into a front end's output: checkpoints written to the
// output while it renders, a farm claim kept fresh, progress told to the
// front end. A still (orb-render without frames) and every frame of the
// frame loop (orb/job/frame_run.h) render this way.
#pragma once

#include <atomic>
#include <optional>
#include <string>

#include "orb/job/film_progress.h"
#include "orb/job/frame_claim.h"
#include "orb/job/image_output.h"
#include "orb/job/render_film.h"
#include "orb/job/render_plan.h"
#include "orb/job/run_stats.h"
#include "orb/render/renderer.h"

namespace orb::job {

// What rendering a film into an output asks beyond its plan: the same for a
// still and for every frame.
struct OutputRun {
    std::optional<double> time_limit;  // --time SECONDS
    std::optional<double> checkpoint;  // --checkpoint SECONDS: the output is rewritten this often
    // The caller's stop flag (orb-render's signal handler sets it), checked
    // between passes and, in the frame loop, before each frame.
    const std::atomic<bool>* cancel = nullptr;
    FilmProgress* progress = nullptr;  // none: nothing is told
};

// The film a still starts from: a resumed plan's (said: "resuming FILE at
// N spp (samples ...)", with a warning when the file holds means only),
// else an empty one at the plan's first sample.
void start_film(const RenderPlan& plan, render::Renderer& renderer);

// Renders `plan` on `renderer`, whose film is set up (start_film, or the
// frame loop's set_up), writing each checkpoint to `output` and refreshing
// `claim` after every pass; `label` ("frame 12: ", or "") starts what the
// progress shows. The outcome's stats name output.path(). The final image
// is the caller's to write (its film still on its way with `read_later`,
// into the memory of `reuse`).
FilmOutcome render_into(render::Renderer& renderer, const RenderPlan& plan, const OutputRun& run, ImageOutput& output,
                        const std::string& label = "", FrameClaim* claim = nullptr, Film reuse = {},
                        bool read_later = false);

// What --stats-json says of a still once its image is written: the film's
// stats, the seconds until the devices could render, and the denoiser's
// times (known once the image is encoded).
RunStats written_stats(const FilmOutcome& outcome, double setup_seconds);

}  // namespace orb::job
