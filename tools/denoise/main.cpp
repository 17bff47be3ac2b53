// orb-denoise: adds a `denoised` layer to an orb-render EXR, made by Intel
// Open Image Denoise from its beauty, albedo and normal layers
// (docs/orb-denoise.md). The work is libdenoise's; this is the front end.
#include <chrono>
#include <cstdio>
#include <string>

#include "orb/cli/exr_output_name.h"
#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/cli/output_file.h"
#include "orb/cli/output_overlap.h"
#include "orb/cli/tool_main.h"
#include "orb/denoise/denoise_exr.h"
#include "orb/denoise/denoiser.h"

namespace {

using orb::cli::UsageError;

const char* kDescription =
    "Denoise an orb-render EXR with Intel Open Image Denoise: adds the layer denoised.R/G/B, keeps every other layer.";

const char* kExamples = R"(Examples:
  orb-render scene.json --spp 16 --passes beauty,albedo,normal -o noisy.exr
  orb-denoise noisy.exr -o denoised.exr
  orb-tonemap denoised.exr --pass denoised -o denoised.png
  orb-render scene.json --spp 16 --passes beauty,albedo,normal -o - | orb-denoise - -o - | orb-tonemap - --pass denoised -o out.png

The input needs the albedo and normal layers. OIDN is loaded at run time:
$ORB_OIDN_LIBRARY, then where scripts/install-deps.sh installs it, then the
loader's search path.

Exit status: 0 denoised, 1 the input is bad or OIDN is missing or failed,
2 usage error. Details: docs/orb-denoise.md)";

struct Arguments {
    std::string input;
    std::string output;
    std::string device = "default";
    std::string quality = "high";
    bool prefilter_aux = orb::denoise::DenoiseSettings{}.prefilter_aux;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", seconds);
    return text;
}

int run(const Arguments& args) {
    if (args.output.empty()) throw UsageError("missing -o/--output (an EXR path, or - for stdout)");
    orb::cli::require_exr_output_name(args.output);
    orb::denoise::DenoiseSettings settings;
    try {
        settings.device = orb::denoise::parse_device_choice(args.device);
        settings.quality = orb::denoise::parse_quality(args.quality);
        settings.prefilter_aux = args.prefilter_aux;
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    // The output is checked and prepared, and OIDN loaded, before the input
    // is read: a missing denoiser fails at once, leaving nothing behind.
    orb::cli::refuse_overlapping_paths({{"INPUT", args.input}}, {{"-o", args.output}});
    orb::cli::OutputFile output(args.output, "-o");
    orb::denoise::Denoiser denoiser(settings);

    const std::string source = orb::cli::is_stdio(args.input) ? "<stdin>" : args.input;
    const std::string bytes = orb::cli::read_input(args.input);
    const auto start = std::chrono::steady_clock::now();
    const std::string denoised = orb::denoise::add_denoised_layer(bytes, source, denoiser);
    const double seconds = seconds_since(start);
    output.write(denoised);
    orb::cli::info("denoised " + source + " in " + seconds_text(seconds) + " (filter set-up " +
                   seconds_text(denoiser.last_setup_seconds()) + ", filter " +
                   seconds_text(denoiser.last_filter_seconds()) + "; " + denoiser.description() + ") -> " +
                   output.display_name());
    return orb::cli::kSuccess;
}

}  // namespace

int main(int argc, char** argv) {
    Arguments args;
    return orb::cli::run_tool(
        argc, argv, "orb-denoise", kDescription,
        [&](CLI::App& app) {
            app.add_option("INPUT", args.input, "orb-render EXR with beauty, albedo and normal ('-' = stdin)")
                ->required();
            app.add_option("-o,--output", args.output, "Output EXR, or - for stdout")->option_text("FILE");
            app.add_option("--device", args.device,
                           "OIDN device: default (a supported GPU, else the CPU), cpu, cuda")
                ->option_text("NAME");
            app.add_option("--quality", args.quality, "Filter quality: high (final frames), balanced, fast")
                ->option_text("NAME");
            app.add_flag("--prefilter-aux,!--no-prefilter-aux", args.prefilter_aux,
                         std::string("Denoise the albedo and normal first, then the beauty guided by them as clean "
                                     "images (OIDN's cleanAux); default ") +
                             (args.prefilter_aux ? "on" : "off"));
            app.footer(kExamples);
        },
        [&] { return run(args); });
}
