// A well-mixed 32-bit integer hash (the "lowbias32" constants found by Chris
// Wellons' hash prospector), for dithering noise and colours keyed by id.
#pragma once

#include <cstdint>

namespace orb::image {

inline std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

}  // namespace orb::image
