// orb-render's command line: the options as typed, before the scene or a
// resumed file fills in what was left out.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "orb/cli/scene_reading.h"
#include "orb/cli/sphere_style_options.h"
#include "orb/request/request_options.h"

namespace orb::render_cli {

// The options that say which render an output holds (--spp, --width,
// --passes, --fps, ...) are orb::request's, shared with orb-frames.
struct RenderOptions : request::RequestOptions {
    std::string scene;   // path or "-"
    // How the scene is read: every importer's options (--radius, --cell, --non-spheres, ...), --environment,
    // --allow-empty (reading.import.allow_empty): as orb-import reads it.
    cli::SceneReading reading;
    std::string output;  // path or "-"
    bool list_devices = false;
    std::string device;
    std::optional<double> time_limit;
    std::optional<double> checkpoint;
    std::string resume;
    std::optional<std::string> compression;
    bool denoise = false;  // --denoise: add the `denoised` layer to the final image (libdenoise)
    std::string stats_json;
    bool benchmark = false;
    double benchmark_seconds = 5.0;
    std::optional<double> time_at;
    // Animations (orb/job/request_settings.h).
    std::optional<std::string> frames;  // --frames SPEC
    std::optional<long> frame;          // --frame N
    bool skip_existing = false;
    bool claim = false;
    bool missing = false;  // --missing: list what would be rendered, render nothing
    double claim_stale_after = 600;   // seconds without a refresh before another host's claim is taken over
    double progress_interval = 5;     // seconds between progress lines when stderr is not a terminal
    std::string kernel_dir;
    bool no_cache = false;
    // Adaptive sampling (docs/design/adaptive-sampling.md).
    std::optional<double> noise_threshold;  // --noise-threshold: a pixel stops below this relative error
    std::optional<double> target_error;     // --target-error: the render stops below this relMSE
    cli::SphereStyleArguments style;  // --color-by, --radius-by, ... (orb/import/sphere_styling.h)
};

void add_render_options(CLI::App& app, RenderOptions& options);

// Combinations CLI11 cannot express; throws orb::cli::UsageError.
void check_option_combinations(const RenderOptions& options);

// True for --frame or --frames.
bool renders_frames(const RenderOptions& options);
// True for frames, and for outputs left alone when complete (--skip-existing,
// --claim, --missing): the frame loop, which prepares each output just before its frame.
bool runs_frame_loop(const RenderOptions& options);

// The frames of --frames (docs/frames.md), in order. Throws orb::cli::UsageError.
std::vector<long> parse_frames_option(const std::string& spec);

}  // namespace orb::render_cli
