#include "render_options.h"

#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "orb/cli/exr_output_name.h"
#include "orb/cli/io.h"
#include "orb/cli/tool_main.h"
#include "orb/exr/passes.h"
#include "orb/render/sample_ranges.h"

namespace orb::render_cli {
namespace {

const CLI::Validator kPositiveSeconds(
    [](std::string& text) -> std::string {
        try {
            std::size_t used = 0;
            const double value = std::stod(text, &used);
            if (used == text.size() && std::isfinite(value) && value > 0) return {};
        } catch (const std::exception&) {
        }
        return "expected a positive number of seconds, got '" + text + "'";
    },
    "SECONDS>0");

const CLI::Validator kFiniteNumber(
    [](std::string& text) -> std::string {
        try {
            std::size_t used = 0;
            const double value = std::stod(text, &used);
            if (used == text.size() && std::isfinite(value)) return {};
        } catch (const std::exception&) {
        }
        return "expected a number, got '" + text + "'";
    },
    "NUMBER");

// A seed is any 64-bit value, written in decimal. CLI11 alone would wrap -1 to
// 2^64-1 and clamp larger values, so distinct seeds would collide: only plain
// digits that fit are accepted.
const CLI::Validator kSeed(
    [](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (!text.empty() && error == std::errc{} && stop == end) return {};
        return "expected a whole number in [0, 18446744073709551615], got '" + text + "'";
    },
    "0..2^64-1");

// START:COUNT, COUNT within what orb:spp (an EXR int) can record.
const CLI::Validator kSampleRange(
    [](std::string& text) -> std::string {
        try {
            const render::SampleRange range = render::parse_sample_range(text);
            if (range.count > static_cast<std::uint64_t>(INT_MAX))
                return "COUNT must be at most 2147483647 (orb:spp is an EXR int), got '" + text + "'";
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
        return {};
    },
    "START:COUNT");

const char* kExamples = R"(Examples:
  orb-render scenes/cornell.json -o cornell.exr
  orb-render scene.json -o out.exr --spp 1024 --checkpoint 10
  orb-render scene.json -o out.exr --time 60 --device 1
  orb-render --resume out.exr scene.json -o out.exr --spp 4096
  orb-render scene.json --sample-range 512:512 -o part2.exr && orb-merge part*.exr -o out.exr
  orb-import cornell.scn | orb-render - -o - | orb-tonemap - -o cornell.png
  orb-render --list-devices
  orb-render --benchmark scenes/cornell.json --width 640 --height 480

Exit status: 0 done, 1 failed or bad input, 2 usage error,
129/130/143 stopped by SIGHUP/SIGINT/SIGTERM (the image so far is written).
Details: docs/orb-render.md)";

}  // namespace

void add_render_options(CLI::App& app, RenderOptions& o) {
    app.add_option("SCENE", o.scene, "Scene file (Orb JSON or binary .orb, .scn, glTF, PLY) or - for stdin");
    app.add_option("-o,--output", o.output, "Output EXR, or - for stdout");
    app.add_flag("--list-devices", o.list_devices, "List OpenCL devices and exit");
    app.add_option("--device", o.device, "Device index or name substring (default: fastest GPU, else CPU)");
    app.add_option("--spp", o.spp, "Samples per pixel to reach (default: the scene's render.spp)")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{INT_MAX}));
    app.add_option("--sample-range", o.sample_range,
                   "Render exactly the samples START ... START+COUNT-1 (a slice of a frame, for orb-merge)")
        ->check(kSampleRange);
    app.add_option("--time", o.time_limit, "Stop after this many seconds of rendering")->check(kPositiveSeconds);
    app.add_option("--checkpoint", o.checkpoint, "Rewrite the output every SECONDS while rendering")
        ->check(kPositiveSeconds);
    app.add_option("--resume", o.resume, "Continue the render stored in this orb-render EXR");
    app.add_option("--seed", o.seed, "Random seed, 0 ... 2^64-1 (default 0)")->check(kSeed);
    app.add_option("--mode", o.mode, "Light transport: global (path tracing) or direct")
        ->check(CLI::IsMember({"global", "direct"}));
    app.add_option("--sampler", o.sampler,
                   "Random numbers: sobol (low discrepancy, default) or independent")
        ->check(CLI::IsMember({"sobol", "independent"}));
    app.add_option("--max-depth", o.max_depth, "Maximum path depth (default: the scene's render.max_depth)")
        ->check(CLI::Range(0, 1024));
    app.add_option("--width", o.width, "Image width (default: the scene's render.width)")->check(CLI::Range(1, 65536));
    app.add_option("--height", o.height, "Image height (default: the scene's render.height)")
        ->check(CLI::Range(1, 65536));
    app.add_flag("--half", o.half, "Store colour layers as HALF (Z and id stay FLOAT)");
    app.add_option("--passes", o.passes,
                   "Layers to write: beauty,direct,indirect,emission,albedo,normal,depth,variance,id or all");
    app.add_option("--stats-json", o.stats_json, "Write the run's figures as JSON to FILE (- for stdout)");
    app.add_flag("--benchmark", o.benchmark, "Time warm-up and timed passes, write no image, print samples_per_second=");
    app.add_option("--benchmark-seconds", o.benchmark_seconds, "Timed part of --benchmark (default 5)")
        ->check(kPositiveSeconds);
    app.add_option("--time-at", o.time_at, "Render an animated scene at this time in seconds")->check(kFiniteNumber);
    app.add_option("--kernel-dir", o.kernel_dir, "Development: load OpenCL kernels from this folder");
    app.add_flag("--no-cache", o.no_cache, "Do not read or write cached kernel binaries");
    app.footer(kExamples);
}

void check_option_combinations(const RenderOptions& o) {
    using cli::UsageError;
    if (o.list_devices) return;
    if (o.scene.empty()) throw UsageError("missing SCENE (a scene file, or - for stdin)");
    if (o.passes) {
        try {
            exr::parse_passes(*o.passes);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--passes: ") + e.what());
        }
    }
    if (o.benchmark) {
        const char* conflicting = !o.output.empty() ? "-o"
                                  : !o.resume.empty() ? "--resume"
                                  : o.checkpoint      ? "--checkpoint"
                                  : o.spp             ? "--spp"
                                  : o.sample_range    ? "--sample-range"
                                  : o.time_limit      ? "--time"
                                  : o.half            ? "--half"
                                  : o.passes          ? "--passes"
                                                      : nullptr;
        if (conflicting)
            throw UsageError(std::string("--benchmark writes no image and takes no ") + conflicting +
                             " (use --benchmark-seconds for its length)");
        return;
    }
    if (o.sample_range && o.spp)
        throw UsageError("--sample-range START:COUNT already says how many samples to render; drop --spp " +
                         std::to_string(*o.spp));
    if (o.output.empty()) throw UsageError("missing -o/--output (an EXR path, or - for stdout)");
    cli::require_exr_output_name(o.output);
    if (cli::is_stdio(o.output) && o.checkpoint)
        throw UsageError("--checkpoint rewrites a file while rendering and cannot go to stdout (-o -)");
    if (cli::is_stdio(o.output) && cli::is_stdio(o.stats_json))
        throw UsageError("-o - and --stats-json - cannot both write to stdout");
    if (cli::is_stdio(o.resume)) throw UsageError("--resume needs an EXR file, not -");
}

}  // namespace orb::render_cli
