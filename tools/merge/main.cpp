// orb-merge: sums partial renders of one frame (orb-render --sample-range
// slices, from any machines) into one EXR (docs/orb-merge.md).
#include <optional>
#include <string>
#include <vector>

#include "orb/cli/exr_output_name.h"
#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/cli/output_file.h"
#include "orb/cli/output_overlap.h"
#include "orb/cli/paths.h"
#include "orb/cli/tool_main.h"
#include "orb/denoise/denoise_film.h"
#include "orb/denoise/denoiser.h"
#include "orb/exr/film_merge.h"

namespace {

using orb::cli::UsageError;

const char* kDescription =
    "Sum partial renders of one frame (orb-render --sample-range slices) into one multi-pass OpenEXR.";

const char* kExamples = R"(Examples:
  orb-render shot.json --sample-range 0:512   -o part0.exr    # on one machine
  orb-render shot.json --sample-range 512:512 -o part1.exr    # on another
  orb-merge part0.exr part1.exr -o shot.exr
  orb-merge part0.exr part1.exr --denoise -o shot.exr         # slices with albedo,normal

Exit status: 0 merged, 1 an input is unreadable or not a slice of the same
render (or the ranges overlap), 2 usage error. Details: docs/orb-merge.md)";

struct Arguments {
    std::vector<std::string> inputs;
    std::string output;
    bool denoise = false;
};

int run(const Arguments& args) {
    if (args.output.empty()) throw UsageError("missing -o/--output (an EXR path, or - for stdout)");
    orb::cli::require_exr_output_name(args.output);
    std::vector<orb::cli::NamedPath> inputs;
    for (const std::string& input : args.inputs) {
        if (orb::cli::is_stdio(input)) throw UsageError("orb-merge reads EXR files, not standard input (-)");
        inputs.push_back({"INPUT", input});
    }
    // The output is checked and prepared before any input is read.
    orb::cli::refuse_overlapping_paths(inputs, {{"-o", args.output}});
    orb::cli::OutputFile output(args.output, "-o");
    // OIDN is loaded before any input is read: a missing denoiser fails at once.
    std::optional<orb::denoise::Denoiser> denoiser;
    if (args.denoise) denoiser.emplace(orb::denoise::DenoiseSettings{});

    std::vector<orb::exr::MergeInput> films;
    for (const std::string& input : args.inputs) films.push_back({input, orb::exr::read_film_exr(input)});
    for (const orb::exr::MergeInput& film : films)
        if (!film.file.exact && !film.file.half) orb::cli::warning(film.path + ": " + orb::exr::kMeansOnly);
    orb::exr::ExrFilm merged = orb::exr::merge_films(std::move(films));
    merged.metadata.version = orb::cli::version_string();
    for (const orb::film::OutOfRange& out : orb::film::sums_out_of_range(merged.film))
        orb::cli::warning(orb::film::describe(out, merged.film.width));

    orb::exr::ExrWriteOptions options;
    options.passes = merged.passes;
    // A merge may be merged again or continued: its exact sums go with it.
    options.exact_sums = true;
    // --denoise: the denoised layer is written by the merged film's one encode.
    std::vector<orb::exr::PostLayerPlanes> post;
    if (denoiser) post.push_back(orb::denoise::denoised_post_layer(*denoiser, "the merged image"));
    output.write(orb::exr::encode_film_exr(merged.film, merged.metadata, options, post));
    orb::cli::info("merged " + std::to_string(args.inputs.size()) + " files: " +
                   std::to_string(merged.film.samples_per_pixel) + " spp (samples " +
                   merged.film.sample_ranges.format() + ")" + (denoiser ? ", denoised" : "") + " -> " +
                   output.display_name());
    return orb::cli::kSuccess;
}

}  // namespace

int main(int argc, char** argv) {
    Arguments args;
    return orb::cli::run_tool(
        argc, argv, "orb-merge", kDescription,
        [&](CLI::App& app) {
            app.add_option("INPUT", args.inputs, "Partial renders of one frame (orb-render EXRs)")->required();
            app.add_option("-o,--output", args.output, "Output EXR, or - for stdout")->option_text("FILE");
            app.add_flag("--denoise", args.denoise,
                         "Add a layer 'denoised' to the merged image (Intel Open Image Denoise; the slices need "
                         "albedo,normal)");
            app.footer(kExamples);
        },
        [&] { return run(args); });
}
