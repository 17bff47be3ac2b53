// The options that say which render an output holds, as orb-render and
// orb-frames --missing take them: the same names, checks and help texts.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

#include "orb/cli/camera_options.h"
#include "orb/cli/orbit_options.h"
#include "orb/job/request_settings.h"

namespace orb::request {

struct RequestOptions {
    std::optional<std::uint64_t> spp;
    std::optional<std::string> sample_range;  // "START:COUNT"
    std::optional<std::uint64_t> seed;
    std::optional<std::string> mode;
    std::optional<std::string> sampler;
    std::optional<int> max_depth;
    std::optional<int> width;
    std::optional<int> height;
    std::optional<std::string> passes;
    bool half = false;
    std::optional<double> fps;
    bool same_seed = false;
    // The camera: part of what an output holds (its matrices are in the EXR).
    cli::CameraOptions camera;
    cli::OrbitOptions orbit;

    bool operator==(const RequestOptions&) const = default;  // RequestOptions{}: none given
};

void add_request_options(CLI::App& app, RequestOptions& options);

// Combinations CLI11 cannot express (--passes' names, --sample-range with
// --spp); throws orb::cli::UsageError.
void check_request_options(const RequestOptions& options);

// What the render job is asked for (orb/job/request_settings.h): each
// option given, else `scene_render` (the scene's render block, or null when
// the scene is not read), else Orb's default; the camera options and the
// orbit as its camera. `animation_frames` is the frame list rendered or
// judged (null for --frame N or a still), `renders_frames` whether frames
// are: they give --orbit its range (orb::cli::resolve_orbit, whose
// UsageError this throws).
job::RequestSettings resolve_request(const RequestOptions& options, const RenderSettings* scene_render,
                                     const std::string* animation_frames = nullptr, bool renders_frames = false);

// SECONDS > 0, finite (also --fps).
const CLI::Validator& positive_number();

}  // namespace orb::request
