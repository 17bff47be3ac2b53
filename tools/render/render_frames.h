// Rendering the frames of an animation (--frame/--frames), and any render
// that leaves complete outputs alone or claims them (--skip-existing,
// --claim): one renderer, so one OpenCL session and one kernel build, for
// every frame; each output prepared just before its frame.
#pragma once

#include "render_options.h"
#include "render_outputs.h"
#include "render_plan.h"

namespace orb::render_cli {

// Returns the exit code: 0 when every frame was rendered or left alone,
// 128 + the signal when interrupted (the frame in flight is written).
int run_frames(RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs);

// --benchmark --frames: what a frame costs besides its samples (posing the
// scene, uploading it, reading the film back, encoding and writing the EXR),
// per frame; the last stdout line is frame_overhead_ms=<mean>.
int run_frames_benchmark(RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs);

}  // namespace orb::render_cli
