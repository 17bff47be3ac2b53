// The frame loop: every job (a frame of an animation, or the one output of
// a render that leaves complete outputs alone) in order, on one renderer
// (one OpenCL session, one kernel build), each frame's scene posed while the
// last one renders and its image written on the background writer's
// threads while the next one renders. Outputs already finished are skipped,
// outputs stopped short are continued, outputs claimed by another host are
// left to it (--skip-existing, --claim).
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "orb/job/frame_claim.h"
#include "orb/job/frame_jobs.h"
#include "orb/job/image_output.h"
#include "orb/job/render_film.h"
#include "orb/job/render_plan.h"
#include "orb/job/run_stats.h"

namespace orb::job {

struct FrameRunOptions {
    bool skip_existing = false;  // finished outputs are skipped, those stopped short continued
    bool claim = false;          // each output is claimed before it renders (frame_claim.h); implies skip_existing
    double claim_stale_after = 600;  // seconds without a refresh before another host's claim is taken over
    const std::atomic<bool>* cancel = nullptr;  // checked before each frame (render_film checks it between passes)
};

// What the front end does for the loop (orb-render: its output files,
// progress lines and messages).
struct FrameRunHooks {
    // The output of a job about to render, ready to be written (orb-render
    // locks it and makes its temporary file). What it throws ends the run.
    std::function<std::unique_ptr<ImageOutput>(const Job&)> prepare_output;
    // Renders the set-up plan into a film (render_film with the front end's
    // progress and checkpoints), its film read later into `reuse`.
    std::function<FilmOutcome(render::Renderer&, const RenderPlan&, ImageOutput& output, const std::string& label,
                              FrameClaim* claim, Film reuse)>
        render;
    // What the line said once a frame's file is in place ends with ("64 spp in 2.1 s ... -> out.exr").
    std::function<std::string(const FilmOutcome&, const render::Renderer&, const ImageOutput&)> summary;
    std::function<void(render::Renderer&)> renderer_made;  // once, when the loop's renderer exists
    std::function<void(const Job&)> skipped;  // an output left alone as finished (orb-render removes a stale lock)
};

struct FramesRun {
    std::vector<RunStats> rendered;  // each frame rendered, in order (its denoise times once written)
    std::vector<long> skipped;       // the frames finished already
    int claimed_elsewhere = 0;
    int continued = 0;
    // Stopped before the first pass of a frame finished: that frame has no image.
    std::optional<std::string> stopped_before_image;  // its label ("frame 8: ", or "")
    std::optional<int> kernel_builds;  // the renderer's, when one was made
};

// Renders `jobs` (frames in the order given). Messages (skipped, claimed,
// continued, written) go to plan.messages. Throws as the writer does when an
// image could not be written, and orb::InputError for a frame that cannot be posed.
FramesRun run_frames(RenderPlan& plan, const std::vector<Job>& jobs, const FrameRunOptions& options,
                     const FrameRunHooks& hooks);

}  // namespace orb::job
