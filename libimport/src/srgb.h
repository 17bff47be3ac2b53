// Private: the sRGB transfer function's inverse (IEC 61966-2-1), for the
// importers whose colours are display values (PLY colours, glTF base-colour
// and emissive textures); the scene holds linear Rec.709.
#pragma once

#include <cmath>

namespace orb::detail {

inline double srgb_to_linear(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

}  // namespace orb::detail
