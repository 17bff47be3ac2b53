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
#include "orb/job/output_film.h"
#include "orb/job/render_film.h"
#include "orb/job/render_plan.h"
#include "orb/job/run_stats.h"

namespace orb::job {

struct FrameRunOptions {
    bool skip_existing = false;  // finished outputs are skipped, those stopped short continued
    bool claim = false;          // each output is claimed before it renders (frame_claim.h); implies skip_existing
    double claim_stale_after = 600;  // seconds without a refresh before another host's claim is taken over
    // How each frame renders into its output (render_into); its cancel flag
    // is also checked before each frame.
    OutputRun film;
};

// What the front end does for the loop (orb-render: its output files and
// messages).
struct FrameRunHooks {
    // The output of a job about to render, ready to be written (orb-render
    // locks it and makes its temporary file). What it throws ends the run.
    std::function<std::unique_ptr<ImageOutput>(const Job&)> prepare_output;
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

// What --stats-json says of a run of the frame loop: for one frame asked
// (or a still's one output) that was rendered, that render's object
// (stats_json); else every frame rendered and those skipped (frames_stats_json).
std::string frames_run_stats_json(const RenderPlan& plan, const FramesRun& run);

}  // namespace orb::job
