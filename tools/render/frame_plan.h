// Animations: which frames to render, the time and seed of each, and where
// each one goes (docs/orb-render.md, "Animations").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace orb::render_cli {

// Neither glTF (keyframe times in seconds) nor Orb's scene format records a
// frame rate, so without --fps frames are 1/24 s apart.
inline constexpr double kDefaultFps = 24.0;

// The scene time of a frame: frame / fps seconds.
double frame_time(long frame, double fps);

// The seed of a frame, so that noise does not stand still on screen:
// SplitMix64's finaliser of (seed XOR the finaliser of frame + 1). The same
// for --frame N and frame N of --frames.
std::uint64_t frame_seed(std::uint64_t seed, long frame);

}  // namespace orb::render_cli
