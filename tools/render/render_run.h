// Running a RenderPlan: the progressive render with checkpoints, the final
// image, statistics; or the benchmark.
#pragma once

#include "render_options.h"
#include "render_outputs.h"
#include "render_plan.h"

namespace orb::render_cli {

// Returns the exit code: 0, or 130/143 when stopped by a signal.
int run_render(const RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs);

int run_benchmark(const RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs);

}  // namespace orb::render_cli
