// Float display values -> integer code values.
#pragma once

#include <cstdint>
#include <vector>

#include "orb/image/image.h"

namespace orb::image {

// 8-bit with rectangular (uniform, one code value wide) dither: each value v
// becomes floor(255 v + u) with u uniform in [0,1) from a hash of the pixel
// position and channel. The expected code is exactly 255 v (no banding bias)
// and every code is within one step of 255 v, so the result stays within
// 1/255 of the float image. Deterministic: the same input gives the same file.
std::vector<uint8_t> quantize_8bit_dithered(const Image& image);

// 8-bit, round to nearest (for when dithering is turned off).
std::vector<uint8_t> quantize_8bit(const Image& image);

// 16-bit, round to nearest: steps of 1/65535 make dithering unnecessary.
std::vector<uint16_t> quantize_16bit(const Image& image);

}  // namespace orb::image
