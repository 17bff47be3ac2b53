// orb-diff: compare two images with metrics and gates a CI job can rely on.
// Exit status: 0 pass (or warn), 1 fail (or warn with --strict), 2 error.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "gates.h"
#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/cli/output_file.h"
#include "orb/cli/output_overlap.h"
#include "orb/cli/number_checks.h"
#include "orb/cli/tool_main.h"
#include "orb/image/color_options.h"
#include "orb/image/compare.h"
#include "orb/image/flip.h"
#include "orb/image/load.h"
#include "orb/image/write.h"
#include "report.h"

namespace fs = std::filesystem;
using namespace orb::image;
using namespace orb::diff;
using orb::cli::UsageError;

namespace {

constexpr int kExitPass = 0, kExitFail = 1, kExitError = 2;

struct Settings {
    std::string reference, test;
    std::string pass = "beauty";
    std::string test_pass;  // --test-pass: the test image's pass, when not --pass
    bool all_passes = false;
    ColorOptions color;
    Gates gates;
    bool strict = false;
    std::string diff_image;
    std::string json;
    double ppd = 0;
};

// FLIP's filters grow linearly with pixels per degree (libimage/src/flip.cpp:
// 2*ceil(0.135*ppd)+1 taps for the colour CSF), so a huge --ppd runs for
// minutes and allocates gigabytes. Below 1 ppd a pixel spans more than a
// degree and the filters are a single tap; 1000 ppd is far beyond any screen
// or print (the eye resolves about 120) and already costs 271 taps, 13 times
// the default 67.
constexpr double kMinPpd = 1, kMaxPpd = 1000;

void add_gate_options(CLI::App& app, GateSet& g, const std::string& kind) {
    using orb::cli::finite_number_in;
    const std::string verb = kind == "fail" ? "Fail" : "Warn";
    const double inf = std::numeric_limits<double>::infinity();
    const auto non_negative = finite_number_in(0, inf, "a finite number >= 0");
    app.add_option("--" + kind + "-rmse", g.rmse, verb + " if RMSE exceeds X")->option_text("X")->check(non_negative);
    app.add_option("--" + kind + "-relmse", g.relmse, verb + " if relative MSE exceeds X")
        ->option_text("X")
        ->check(non_negative);
    app.add_option("--" + kind + "-flip", g.flip, verb + " if mean FLIP exceeds X (colour passes)")
        ->option_text("X")
        ->check(non_negative);
    app.add_option("--" + kind + "-percent", g.percent,
                   verb + " if more than P% of pixels differ by more than --" + kind + "-threshold")
        ->option_text("P")
        ->check(finite_number_in(0, 100, "a percentage in [0, 100]"));
    app.add_option("--" + kind + "-threshold", g.threshold,
                   "Per-channel difference that counts a pixel as different (default: 1e-6 + 1e-4*max(|a|,|b|))")
        ->option_text("T")
        ->check(non_negative);
}

// OUT for one pass; OUT.<pass>.ext when several passes are compared.
std::string diff_image_path(const std::string& path, const std::string& pass, bool several) {
    if (!several) return path;
    fs::path p(path);
    return (p.parent_path() / (p.stem().string() + "." + pass + p.extension().string())).string();
}

// PNG unless the name says otherwise: stdout, a device or a FIFO has no extension.
WriteOptions heatmap_write_options(const std::string& path) {
    WriteOptions options;
    options.format = extension_of(path).empty() ? "png" : extension_of(path);
    return checked_write_options(options);
}

std::vector<std::string> passes_to_compare(const Settings& s, const LoadedImage& a, const LoadedImage& b) {
    if (!s.all_passes) return {s.pass};
    const auto in_a = available_passes(a.image), in_b = available_passes(b.image);
    std::vector<std::string> common;
    for (const auto& p : in_a) {
        if (std::find(in_b.begin(), in_b.end(), p) != in_b.end())
            common.push_back(p);
        else
            orb::cli::warning("pass '" + p + "' is only in " + display_name(a.source) + "; not compared");
    }
    for (const auto& p : in_b)
        if (std::find(in_a.begin(), in_a.end(), p) == in_a.end())
            orb::cli::warning("pass '" + p + "' is only in " + display_name(b.source) + "; not compared");
    if (common.empty()) throw orb::InputError("the images have no pass in common");
    return common;
}

int run(const Settings& s) {
    if (s.color.list) {
        return orb::cli::print_to_stdout(load_color_config(s.color).listing());
    }
    if (s.reference.empty() || s.test.empty()) throw UsageError("need two images: orb-diff A B (see --help)");
    if (s.reference == "-" && s.test == "-") throw UsageError("only one of the two images can be '-' (stdin)");
    if (s.all_passes && s.pass != "beauty") throw UsageError("--pass and --all-passes exclude each other");
    if (s.all_passes && !s.test_pass.empty()) throw UsageError("--test-pass and --all-passes exclude each other");
    const bool through_display = !s.color.display.empty() || !s.color.view.empty();
    if (!s.color.look.empty() && !through_display) throw UsageError("--look needs --display/--view");

    std::vector<orb::cli::NamedPath> inputs{{"reference", s.reference}, {"test", s.test}};
    if (!s.color.config_path.empty()) inputs.push_back({"--config", s.color.config_path});
    std::vector<orb::cli::NamedPath> outputs;
    if (!s.json.empty()) outputs.push_back({"--json", s.json});
    orb::cli::refuse_overlapping_paths(inputs, outputs);
    std::optional<orb::cli::OutputFile> json_output;
    if (!s.json.empty()) json_output.emplace(s.json, "--json");

    const ColorConfig config = load_color_config(s.color);
    const LoadedImage a = load_image(s.reference);
    const LoadedImage b = load_image(s.test);

    CompareSettings cs;
    cs.config = &config;
    cs.through_display = through_display;
    cs.input_space = s.color.input_space;
    if (through_display) {
        DisplayView request{config.scene_linear(), s.color.display, s.color.view, s.color.look, 0.0};
        cs.view = resolve_display_view(config, request);
    }
    cs.ppd = s.ppd;
    cs.thresholds = {s.gates.fail_tolerance(), s.gates.warn_tolerance()};
    cs.want_heatmap = !s.diff_image.empty();
    cs.test_pass = s.test_pass;

    const std::vector<std::string> passes = passes_to_compare(s, a, b);
    if (s.diff_image == "-" && passes.size() > 1) throw UsageError("--diff-image - (stdout) needs a single pass");
    // One heatmap per pass, named only now that the passes are known; each is
    // checked and prepared before the comparison runs.
    std::vector<orb::cli::OutputFile> heatmap_outputs;
    std::optional<WriteOptions> heatmap_options;
    if (!s.diff_image.empty()) {
        const std::size_t first_heatmap = outputs.size();
        for (const std::string& pass : passes)
            outputs.push_back({"--diff-image", diff_image_path(s.diff_image, pass, passes.size() > 1)});
        orb::cli::refuse_overlapping_paths(inputs, outputs);
        heatmap_options = heatmap_write_options(s.diff_image);
        for (std::size_t i = first_heatmap; i < outputs.size(); ++i)
            heatmap_outputs.emplace_back(outputs[i].path, outputs[i].option);
    }

    std::vector<PassResult> results;
    Verdict overall = Verdict::Pass;
    for (const std::string& pass : passes) {
        PassResult r{compare_pass(a, b, pass, cs), {}};
        r.outcome = judge(r.comparison, s.gates);
        overall = std::max(overall, r.outcome.verdict);
        results.push_back(std::move(r));
    }

    for (std::size_t i = 0; i < heatmap_outputs.size(); ++i)
        heatmap_outputs[i].write(encode_image(*results[i].comparison.heatmap, *heatmap_options));

    const int code = overall == Verdict::Fail ? kExitFail
                     : overall == Verdict::Warn && s.strict ? kExitFail
                                                             : kExitPass;
    if (!s.json.empty()) {
        nlohmann::json report = {{"reference", display_name(s.reference)},
                                 {"test", display_name(s.test)},
                                 {"config", config.source()},
                                 {"comparison",
                                  {{"through_display", through_display},
                                   {"display", through_display ? nlohmann::json(cs.view.display) : nlohmann::json(nullptr)},
                                   {"view", through_display ? nlohmann::json(cs.view.view) : nlohmann::json(nullptr)},
                                   {"look", cs.view.look.empty() ? nlohmann::json(nullptr) : nlohmann::json(cs.view.look)},
                                   {"flip_ppd", s.ppd > 0 ? s.ppd : default_flip_ppd()}}},
                                 {"thresholds", gates_json(s.gates)},
                                 {"strict", s.strict},
                                 {"passes", nlohmann::json::array()},
                                 {"verdict", verdict_name(overall)},
                                 {"exit_code", code}};
        for (const auto& r : results) report["passes"].push_back(pass_json(r, s.gates));
        json_output->write(report.dump(2) + "\n");
    }
    // The summary comes last, so that a reader who closes it early
    // (`orb-diff ... | head -1`) still leaves every file written.
    if (!orb::cli::quiet()) {
        std::ostringstream summary;
        for (const auto& r : results) summary << summary_line(r, s.gates) << "\n";
        summary << "verdict: " << verdict_name(overall)
                << (overall == Verdict::Warn && s.strict ? " (strict: fails)" : "") << "\n";
        // With the JSON report on stdout, the summary moves to stderr.
        if (s.json == "-")
            std::cerr << summary.str() << std::flush;
        else if (orb::cli::print_to_stdout(summary.str()) != orb::cli::kSuccess)
            return kExitError;
    }
    return code;
}

}  // namespace

int main(int argc, char** argv) {
    Settings s;
    return orb::cli::run_tool(
        argc, argv, "orb-diff", "Compare two images (any OIIO format) with metrics, FLIP and CI gates",
        [&](CLI::App& app) {
            app.add_option("reference", s.reference, "Reference image A ('-' = stdin)");
            app.add_option("test", s.test, "Test image B ('-' = stdin)");
            app.add_option("--pass,--layer", s.pass,
                           "Pass to compare (default beauty): direct, indirect, albedo, normal, depth, denoised, ...")
                ->option_text("NAME");
            app.add_option("--test-pass,--test-layer", s.test_pass,
                           "Compare this pass of the test image with --pass of the reference (e.g. denoised)")
                ->option_text("NAME");
            app.add_flag("--all-passes", s.all_passes, "Compare every pass the two images have in common");
            add_color_options(app, s.color);
            add_gate_options(app, s.gates.fail, "fail");
            add_gate_options(app, s.gates.warn, "warn");
            app.add_flag("--strict", s.strict, "Treat warnings as failures (exit 1)");
            app.add_option("--diff-image", s.diff_image, "Write an error heatmap (FLIP, magma colour map)")
                ->option_text("OUT");
            app.add_option("--json", s.json, "Write a JSON report ('-' = stdout)")->option_text("FILE");
            app.add_option("--ppd", s.ppd,
                           "FLIP observer: pixels per degree, 1 to 1000 (default 67, a 4K 0.7 m monitor at 0.7 m)")
                ->option_text("PPD")
                ->check(orb::cli::finite_number_in(kMinPpd, kMaxPpd, "pixels per degree in [1, 1000]"));
            app.footer(
                "Examples:\n"
                "  orb-diff reference.exr render.exr --fail-flip 0.05 --warn-flip 0.02\n"
                "  orb-diff golden.png out.png --fail-percent 0.5 --fail-threshold 0.02 --diff-image diff.png\n"
                "  orb-diff a.exr b.exr --all-passes --fail-rmse 0.01 --json report.json\n"
                "  orb-diff converged.exr denoised.exr --test-pass denoised   # its denoised layer against the beauty\n"
                "  orb-diff a.exr b.exr --display sRGB --view Filmic --fail-flip 0.1\n"
                "  orb-render scene.json -o - | orb-diff golden.exr - --fail-relmse 0.001\n"
                "Metrics run over R,G,B (alpha is not compared). Without any --fail-* option, any\n"
                "channel differing by more than float rounding fails: |a-b| > 1e-6 + 1e-4*max(|a|,|b|).\n"
                "Exit status: 0 pass (also warn, unless --strict), 1 fail, 2 error (missing, unreadable or\n"
                "truncated image, different sizes, a pass missing in one image, bad usage).");
        },
        [&]() -> int {
            // run_tool maps bad input to 1, but for orb-diff 1 means "the images differ":
            // every error must be 2 so a CI job can tell the two apart.
            try {
                return run(s);
            } catch (const UsageError&) {
                throw;
            } catch (const std::exception& e) {
                orb::cli::error(e.what());
                return kExitError;
            }
        });
}
