// --orbit DEGREES: a turntable over the frames of an animation
// (docs/orb-render.md, "Camera"). Frame f's camera depends on f and the
// whole animation's frame range only, so every process that renders frame f
// (a --frames run, a --claim worker, --frame f, an orb-farm task) and every
// judge of its output (--skip-existing, --missing, orb-frames) agrees.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "orb/scene/scene.h"

namespace orb::cli {

struct OrbitOptions {
    std::optional<double> degrees;      // --orbit DEGREES
    std::optional<std::string> frames;  // --orbit-frames LIST: the whole animation's frames

    bool operator==(const OrbitOptions&) const = default;
};

void add_orbit_options(CLI::App& app, OrbitOptions& options);

// An orbit of `degrees` over the frames first ... last (the lowest and
// highest frame numbers its list writes).
struct Orbit {
    double degrees = 0;
    long first = 0, last = 0;

    double angle_deg(long frame) const;      // orb::orbit_angle_deg
    Camera turn(const Camera& camera, long frame) const;  // the camera of `frame`
};

// The orbit asked for: its frame range from --orbit-frames, else from
// `animation_frames` (the --frames list being rendered or judged; null with
// --frame N or a still, which then need --orbit-frames / cannot orbit).
// Throws orb::cli::UsageError.
std::optional<Orbit> resolve_orbit(const OrbitOptions& options, const std::string* animation_frames,
                                   bool renders_frames);

}  // namespace orb::cli
