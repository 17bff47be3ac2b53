// Adaptive sampling's per-pixel stopping rule (docs/design/adaptive-sampling.md):
// which pixels keep sampling after a decision, from the pixels' estimated
// errors (pixel_error.h).
#pragma once

#include <cstdint>
#include <vector>

namespace orb::film {

// A pixel is noisy while its estimated relative error, the square root of
// its relMSE estimate, is at least `noise_threshold` (an unknown error,
// infinity, is noisy). The pixels that keep sampling are the `candidates`
// (ascending row-major indices: the pixels still sampling) that are noisy or
// have a noisy pixel among their eight neighbours: a pixel whose few samples
// happened to agree (a caustic none of them has found yet) stops less
// readily beside one whose samples did not. Ascending, a subset of
// `candidates`: a pixel that stopped does not start again in the same run.
std::vector<std::uint32_t> pixels_still_sampling(const std::vector<double>& pixel_relmse, int width, int height,
                                                 double noise_threshold,
                                                 const std::vector<std::uint32_t>& candidates);

}  // namespace orb::film
