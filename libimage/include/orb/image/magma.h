// The "magma" perceptually uniform colour map (van der Walt and Smith,
// matplotlib, released to the public domain under CC0), which FLIP uses for
// its error maps: 0 is near-black, 1 is pale yellow.
#pragma once

#include <array>

namespace orb::image {

// Colour for a value in [0,1] (clamped; NaN maps to 1): display-encoded RGB.
std::array<float, 3> magma(float value);

}  // namespace orb::image
