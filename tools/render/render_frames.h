// Rendering the frames of an animation (--frame/--frames), and any render
// that leaves complete outputs alone or claims them (--skip-existing,
// --claim): one renderer, so one OpenCL session and one kernel build, for
// every frame; each output prepared just before its frame.
#pragma once

#include <vector>

#include "orb/job/frame_jobs.h"
#include "orb/job/render_plan.h"
#include "render_options.h"
#include "render_outputs.h"

namespace orb::render_cli {

// One job per frame (its output from the -o pattern), or the one output.
std::vector<job::Job> jobs_of(const job::RenderPlan& plan, const RenderOptions& options);

// "device: NAME (PLATFORM)" once the frames' renderer is made, and from
// then on a signal ends the frame in flight gracefully (before, during the
// kernel build, there is nothing to save).
void on_frames_renderer(render::Renderer& renderer);

// Returns the exit code: 0 when every frame was rendered or left alone,
// 128 + the signal when interrupted (the frame in flight is written).
// --missing prints what --skip-existing would render and renders nothing.
int run_frames(job::RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs);

}  // namespace orb::render_cli
