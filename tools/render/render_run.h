// Running a RenderPlan: the progressive render with checkpoints, the final
// image, statistics; or the benchmark.
#pragma once

#include "orb/job/render_plan.h"
#include "render_options.h"
#include "render_outputs.h"

namespace orb::render_cli {

// Returns the exit code: 0, or 130/143 when stopped by a signal.
int run_render(const job::RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs);

// --benchmark: the speed of passes; the last stdout line is samples_per_second=<rate>.
int run_benchmark(const job::RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs);

// --benchmark --frames: what a frame costs besides its samples (posing the
// scene, uploading it, reading the film back, encoding and writing the EXR),
// per frame; the last stdout line is frame_overhead_ms=<mean>.
int run_frames_benchmark(job::RenderPlan& plan, const RenderOptions& options);

}  // namespace orb::render_cli
