// orb-render: renders an Orb scene with OpenCL, pass after pass, into a
// multi-pass OpenEXR (docs/orb-render.md).
#include <chrono>
#include <sstream>

#include "device_listing.h"
#include "orb/cli/development_knobs.h"
#include "orb/cli/io.h"
#include "orb/cli/tool_main.h"
#include "orb/import/importers.h"
#include "render_options.h"
#include "command_line_plan.h"
#include "render_outputs.h"
#include "render_frames.h"
#include "render_run.h"

int main(int argc, char** argv) {
    using namespace orb::render_cli;
    RenderOptions options;
    return orb::cli::run_tool(
        argc, argv, "orb-render",
        "Render a scene (" + orb::readable_file_names() + ") with OpenCL path tracing into a multi-pass OpenEXR.",
        [&](CLI::App& app) { add_render_options(app, options); },
        [&]() -> int {
            check_option_combinations(options);
            // The development knobs before anything else: a malformed one
            // fails before a byte is read or an output locked.
            const orb::render::DevelopmentKnobs knobs = orb::cli::development_knobs_from_environment();
            if (options.list_devices) {
                std::ostringstream listing;
                print_device_list(listing);
                return orb::cli::print_to_stdout(listing.str());
            }
            // Outputs first: a render that cannot be written must fail before
            // it reads a byte or builds a kernel, and the lock taken here also
            // covers reading the file that --resume continues in place.
            RenderOutputs outputs = prepare_render_outputs(options);
            const auto reading = std::chrono::steady_clock::now();
            orb::job::RenderPlan plan = make_render_plan(options, knobs);
            plan.read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - reading).count();
            if (options.benchmark)
                return renders_frames(options) ? run_frames_benchmark(plan, options)
                                               : run_benchmark(plan, options, outputs);
            // Frames, and outputs left alone when complete, are prepared one at a time.
            if (runs_frame_loop(options)) return run_frames(plan, options, outputs);
            return run_render(plan, options, outputs);
        });
}
