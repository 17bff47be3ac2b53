// Rendering the frames of an animation (--frame/--frames), and any render
// that leaves complete outputs alone or claims them (--skip-existing,
// --claim): one renderer, so one OpenCL session and one kernel build, for
// every frame; each output prepared just before its frame.
#pragma once

#include "job_names.h"
#include "render_options.h"
#include "render_outputs.h"

namespace orb::render_cli {

// Returns the exit code: 0 when every frame was rendered or left alone,
// 128 + the signal when interrupted (the frame in flight is written).
// One job per frame (its output from the -o pattern), or the one output.
std::vector<Job> jobs_of(const RenderPlan& plan, const RenderOptions& options);

// "device: NAME (PLATFORM)" once the frames' renderer is made, and from
// then on a signal ends the frame in flight gracefully (before, during the
// kernel build, there is nothing to save).
void on_frames_renderer(render::Renderer& renderer);

int run_frames(RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs);

}  // namespace orb::render_cli
