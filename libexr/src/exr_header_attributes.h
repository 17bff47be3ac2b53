// The attributes orb-render adds to an EXR header (orb:* and the standard
// camera matrices), as one list that both writers apply: OpenEXR's C++
// library (PIZ, RLE) and the parallel scanline writer (NONE, ZIP, ZIPS).
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "orb/exr/film_exr.h"

namespace orb::exr::detail {

struct HeaderAttribute {
    std::string name;
    std::variant<int, double, std::string, Matrix44> value;  // int, double, string, m44f
};

// Throws std::invalid_argument for a value an EXR int cannot hold.
std::vector<HeaderAttribute> header_attributes(const Film& film, const ExrMetadata& metadata,
                                               const ExrWriteOptions& options);

}  // namespace orb::exr::detail
