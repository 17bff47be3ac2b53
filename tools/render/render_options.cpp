#include "render_options.h"

#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "orb/import/importers.h"
#include "orb/cli/exr_output_name.h"
#include "orb/cli/frame_spec.h"
#include "orb/cli/io.h"
#include "orb/cli/number_checks.h"
#include "orb/cli/orbit_options.h"
#include "orb/cli/tool_main.h"
#include "orb/exr/film_exr.h"

namespace orb::render_cli {
namespace {

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

const char* kExamples = R"(Examples:
  orb-render scenes/cornell.json -o cornell.exr
  orb-render scene.json -o out.exr --spp 1024 --checkpoint 10
  orb-render scene.json -o out.exr --time 60 --device 1
  orb-render --resume out.exr scene.json -o out.exr --spp 4096
  orb-render scene.json --sample-range 512:512 -o part2.exr && orb-merge part*.exr -o out.exr
  orb-render scene.json -o out.exr --spp 4096 --noise-threshold 0.02 --target-error 0.0005
  orb-import cornell.scn | orb-render - -o - | orb-tonemap - -o cornell.png
  orb-render shot.glb --frames 1-240 -o shots/beauty.%04d.exr
  orb-render shot.glb --frame 48 -o shots/beauty.####.exr --skip-existing
  orb-render shot.glb --frames 1-240 -o shots/beauty.%04d.exr --spp 256 --missing
  orb-render scan.orb --camera-position 0,1,4 --look-at 0,0.5,0 --vfov 35 -o scan.exr
  orb-render scan.orb --orbit 360 --frames 0-119 -o turntable/scan.%04d.exr
  orb-render --list-devices
  orb-render --benchmark scenes/cornell.json --width 640 --height 480

Exit status: 0 done, 1 failed or bad input, 2 usage error,
129/130/143 stopped by SIGHUP/SIGINT/SIGTERM (the image so far is written).
Details: docs/orb-render.md)";

}  // namespace

void add_render_options(CLI::App& app, RenderOptions& o) {
    const CLI::Validator& seconds = request::positive_number();
    app.add_option("SCENE", o.scene, "Scene file (" + orb::readable_file_names() + ") or - for stdin");
    app.add_flag("--allow-empty", o.reading.import.allow_empty, "Render a scene without spheres instead of failing");
    app.add_option("-o,--output", o.output, "Output EXR, or - for stdout");
    app.add_flag("--list-devices", o.list_devices, "List OpenCL devices and exit");
    app.add_option("--device", o.device, "Device index or name substring (default: fastest GPU, else CPU)");
    request::add_request_options(app, o);
    const CLI::Validator positive = cli::finite_number_where([](double v) { return v > 0; }, "a number > 0");
    app.add_option("--noise-threshold", o.noise_threshold,
                   "Adaptive sampling: a pixel stops once its estimated relative error is below T (0.01: 1%); "
                   "--spp stays the most a pixel gets")
        ->check(positive)
        ->option_text("T");
    app.add_option("--target-error", o.target_error,
                   "Stop once the image's estimated relMSE (as orb-diff's relmse) is below E")
        ->check(positive)
        ->option_text("E");
    cli::add_sphere_style_options(app, o.style);
    cli::add_scene_reading_options(app, o.reading);
    app.add_option("--time", o.time_limit, "Stop after this many seconds of rendering")->check(seconds);
    app.add_option("--checkpoint", o.checkpoint, "Rewrite the output every SECONDS while rendering")->check(seconds);
    app.add_option("--resume", o.resume, "Continue the render stored in this orb-render EXR")->option_text("FILE");
    app.add_option("--compression", o.compression,
                   "EXR compression, all lossless: zip (default), zips, piz, rle or none")
        ->check(CLI::IsMember(exr::compression_names()));
    app.add_flag("--denoise", o.denoise,
                 "Add a layer 'denoised' to the final image (Intel Open Image Denoise; adds albedo,normal to --passes)");
    app.add_option("--stats-json", o.stats_json, "Write the run's figures as JSON to FILE (- for stdout)");
    app.add_flag("--benchmark", o.benchmark, "Time warm-up and timed passes, write no image, print samples_per_second=");
    app.add_option("--benchmark-seconds", o.benchmark_seconds, "Timed part of --benchmark (default 5)")->check(seconds);
    app.add_option("--time-at", o.time_at, "Render an animated scene at this time in seconds")->check(kFiniteNumber);
    app.add_option("--frames", o.frames,
                   "Render these frames of an animation: 1-240, 1-240x2 (every 2nd), 1,5,9-12; -o needs a frame "
                   "number, %04d or ####")
        ->option_text("SPEC");
    app.add_option("--frame", o.frame, "Render one frame of an animation (time = frame / fps)")
        ->check(CLI::Range(0L, static_cast<long>(cli::kMaxFrameNumber)));
    app.add_flag("--skip-existing", o.skip_existing,
                 "Finish outputs: leave those that hold this render alone, continue those that stopped short, "
                 "render the others again");
    app.add_flag("--claim", o.claim,
                 "Claim each frame with OUT.claim before rendering it, so machines sharing the folder split the "
                 "frames (implies --skip-existing)");
    app.add_option("--claim-stale-after", o.claim_stale_after,
                   "Seconds after which another host's claim that was not refreshed is taken over (default 600)")
        ->check(seconds);
    app.add_flag("--missing", o.missing,
                 "Render nothing: print the frames (or the output) that --skip-existing would render, one a line, "
                 "with why on stderr");
    app.add_option("--progress-interval", o.progress_interval,
                   "Seconds between progress lines when stderr is not a terminal (default 5)")
        ->check(seconds);
    app.add_option("--kernel-dir", o.kernel_dir, "Development: load OpenCL kernels from this folder");
    app.add_flag("--no-cache", o.no_cache, "Do not read or write cached kernel binaries");
    app.footer(kExamples);
}

void check_option_combinations(const RenderOptions& o) {
    using cli::UsageError;
    if (o.list_devices) return;
    if (o.scene.empty()) throw UsageError("missing SCENE (a scene file, or - for stdin)");
    request::check_request_options(o);
    if (o.frame && o.frames) throw UsageError("--frame N and --frames SPEC exclude each other");
    cli::resolve_orbit(o.orbit, o.frames ? &*o.frames : nullptr, renders_frames(o));  // throws for a bad --orbit
    std::size_t frame_count = o.frame ? 1 : 0;
    if (o.frames) frame_count = parse_frames_option(*o.frames).size();
    if (renders_frames(o)) {
        const char* conflicting = o.time_at            ? "--time-at (the time is frame / fps)"
                                  : !o.resume.empty() ? "--resume (--skip-existing continues every frame that stopped short)"
                                                      : nullptr;
        if (conflicting) throw UsageError(std::string("--frame/--frames take no ") + conflicting);
    } else {
        const char* frame_only = o.fps ? "--fps" : o.same_seed ? "--same-seed" : nullptr;
        if (frame_only) throw UsageError(std::string(frame_only) + " needs --frame N or --frames SPEC");
    }
    // Each frame of --frames is an adaptive render of its own; one that ended
    // on its rule is finished for --skip-existing, --claim and --missing
    // (orb:adaptiveStop). A benchmark times passes over every pixel, whose
    // work adaptive sampling would change from pass to pass.
    if ((o.noise_threshold || o.target_error) && o.benchmark)
        throw UsageError("adaptive sampling (--noise-threshold, --target-error) stops pixels and frames on their "
                         "noise, and --benchmark times passes over every pixel: it takes no --benchmark");
    if (!o.resume.empty() && (o.skip_existing || o.claim))
        throw UsageError(std::string(o.claim ? "--claim" : "--skip-existing") + " and --resume exclude each other");
    if (o.missing) {
        const char* conflicting = o.benchmark              ? "--benchmark"
                                  : !o.resume.empty()      ? "--resume"
                                  : o.claim                ? "--claim"
                                  : !o.stats_json.empty() ? "--stats-json"
                                                           : nullptr;
        if (conflicting) throw UsageError(std::string("--missing renders nothing and takes no ") + conflicting);
    }
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
                                  : o.compression && !renders_frames(o) ? "--compression (but --benchmark --frames takes it)"
                                  : o.denoise && !renders_frames(o) ? "--denoise (but --benchmark --frames takes it)"
                                                      : nullptr;
        if (conflicting)
            throw UsageError(std::string("--benchmark writes no image and takes no ") + conflicting +
                             " (use --benchmark-seconds for its length)");
        return;
    }
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
    if (o.missing && cli::is_stdio(o.output)) throw UsageError("--missing needs an output file, not -o -");
}

bool renders_frames(const RenderOptions& o) { return o.frame.has_value() || o.frames.has_value(); }

bool runs_frame_loop(const RenderOptions& o) { return renders_frames(o) || o.skip_existing || o.claim || o.missing; }

std::vector<long> parse_frames_option(const std::string& spec) {
    try {
        const cli::FrameSpec parsed = cli::parse_frame_spec(spec);
        return std::vector<long>(parsed.begin(), parsed.end());
    } catch (const cli::UsageError& e) {
        throw cli::UsageError(std::string("--frames: ") + e.what());
    }
}

}  // namespace orb::render_cli
