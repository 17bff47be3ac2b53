// orb-render: renders an Orb scene with OpenCL, pass after pass, into a
// multi-pass OpenEXR (docs/orb-render.md).
#include <iostream>

#include "device_listing.h"
#include "orb/cli/tool_main.h"
#include "render_options.h"
#include "render_outputs.h"
#include "render_plan.h"
#include "render_run.h"

int main(int argc, char** argv) {
    using namespace orb::render_cli;
    RenderOptions options;
    return orb::cli::run_tool(
        argc, argv, "orb-render",
        "Render a scene (Orb JSON or binary .orb, .scn, glTF, PLY) with OpenCL path tracing into a multi-pass OpenEXR.",
        [&](CLI::App& app) { add_render_options(app, options); },
        [&]() -> int {
            check_option_combinations(options);
            if (options.list_devices) {
                print_device_list(std::cout);
                return orb::cli::kSuccess;
            }
            // Outputs first: a render that cannot be written must fail before
            // it reads a byte or builds a kernel, and the lock taken here also
            // covers reading the file that --resume continues in place.
            RenderOutputs outputs = prepare_render_outputs(options);
            const RenderPlan plan = make_render_plan(options);
            return options.benchmark ? run_benchmark(plan, options, outputs) : run_render(plan, options, outputs);
        });
}
