#include "render_options.h"

#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "orb/cli/exr_output_name.h"
#include "orb/cli/frame_spec.h"
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
  orb-render shot.glb --frames 1-240 -o shots/beauty.%04d.exr
  orb-render shot.glb --frame 48 -o shots/beauty.####.exr --skip-existing
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
                   "Layers to write (only these are computed; with --benchmark, the layers to time): beauty,direct,indirect,emission,albedo,normal,depth,variance,id or all");
    app.add_option("--stats-json", o.stats_json, "Write the run's figures as JSON to FILE (- for stdout)");
    app.add_flag("--benchmark", o.benchmark, "Time warm-up and timed passes, write no image, print samples_per_second=");
    app.add_option("--benchmark-seconds", o.benchmark_seconds, "Timed part of --benchmark (default 5)")
        ->check(kPositiveSeconds);
    app.add_option("--time-at", o.time_at, "Render an animated scene at this time in seconds")->check(kFiniteNumber);
    app.add_option("--frames", o.frames,
                   "Render these frames of an animation: 1-240, 1-240x2 (every 2nd), 1,5,9-12; -o needs a frame "
                   "number, %04d or ####")
        ->option_text("SPEC");
    app.add_option("--frame", o.frame, "Render one frame of an animation (time = frame / fps)")
        ->check(CLI::Range(0L, static_cast<long>(cli::kMaxFrameNumber)));
    app.add_option("--fps", o.fps, "Frames per second for --frame/--frames (default 24)")->check(kPositiveSeconds);
    app.add_flag("--same-seed", o.same_seed, "Every frame with --seed itself, not a seed derived from the frame");
    app.add_flag("--skip-existing", o.skip_existing,
                 "Leave outputs that are complete (readable, at their target spp) alone; render the others");
    app.add_flag("--claim", o.claim,
                 "Claim each frame with OUT.claim before rendering it, so machines sharing the folder split the "
                 "frames (implies --skip-existing)");
    app.add_option("--claim-stale-after", o.claim_stale_after,
                   "Seconds after which another host's claim that was not refreshed is taken over (default 600)")
        ->check(kPositiveSeconds);
    app.add_option("--progress-interval", o.progress_interval,
                   "Seconds between progress lines when stderr is not a terminal (default 5)")
        ->check(kPositiveSeconds);
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
    if (o.frame && o.frames) throw UsageError("--frame N and --frames SPEC exclude each other");
    std::size_t frame_count = o.frame ? 1 : 0;
    if (o.frames) frame_count = parse_frames_option(*o.frames).size();
    if (renders_frames(o)) {
        const char* conflicting = o.time_at            ? "--time-at (the time is frame / fps)"
                                  : !o.resume.empty() ? "--resume (render incomplete frames again)"
                                                      : nullptr;
        if (conflicting) throw UsageError(std::string("--frame/--frames take no ") + conflicting);
    } else {
        const char* frame_only = o.fps ? "--fps" : o.same_seed ? "--same-seed" : nullptr;
        if (frame_only) throw UsageError(std::string(frame_only) + " needs --frame N or --frames SPEC");
    }
    if (!o.resume.empty() && (o.skip_existing || o.claim))
        throw UsageError(std::string(o.claim ? "--claim" : "--skip-existing") + " and --resume exclude each other");
    if (o.benchmark) {
        if (o.skip_existing || o.claim)
            throw UsageError("--benchmark writes no image and takes no --skip-existing or --claim");
        const char* conflicting = !o.output.empty() ? "-o"
                                  : !o.resume.empty() ? "--resume"
                                  : o.checkpoint      ? "--checkpoint"
                                  : o.spp && !renders_frames(o) ? "--spp (but --benchmark --frames takes it, per frame)"
                                  : o.sample_range    ? "--sample-range"
                                  : o.time_limit      ? "--time"
                                  : o.half            ? "--half"
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
    // Without --frame/--frames, -o is a plain name, '%' and '#' included.
    const int fields = renders_frames(o) ? cli::count_frame_fields(o.output) : 0;
    if (frame_count > 1 && fields == 0) {
        throw UsageError("--frames renders " + std::to_string(frame_count) +
                         " frames: -o needs a frame number, e.g. shots/beauty.%04d.exr or shots/beauty.####.exr");
    }
    if (o.claim && cli::is_stdio(o.output)) throw UsageError("--claim needs an output file, not -o -");
    if (o.skip_existing && cli::is_stdio(o.output)) throw UsageError("--skip-existing needs an output file, not -o -");
}

bool renders_frames(const RenderOptions& o) { return o.frame.has_value() || o.frames.has_value(); }

std::vector<long> parse_frames_option(const std::string& spec) {
    try {
        const cli::FrameSpec parsed = cli::parse_frame_spec(spec);
        return std::vector<long>(parsed.begin(), parsed.end());
    } catch (const cli::UsageError& e) {
        throw cli::UsageError(std::string("--frames: ") + e.what());
    }
}

}  // namespace orb::render_cli
