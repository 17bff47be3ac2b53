// Private: the sRGB transfer function's inverse (IEC 61966-2-1), encoded V in
// [0, 1] -> linear, in float as the image code computes.
#pragma once

#include <cmath>

namespace orb::image {

inline float srgb_to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

}  // namespace orb::image
