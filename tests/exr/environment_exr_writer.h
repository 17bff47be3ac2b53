// Writing environment-map EXR files for tests, with OpenEXR directly (so the
// tests do not depend on the reader they check).
#pragma once

#include <string>
#include <vector>

namespace orb::exr::testing {

struct MapFile {
    int width = 0;
    int height = 0;
    std::vector<std::string> channels{"R", "G", "B"};
    std::vector<float> values;  // per pixel, one value per channel in `channels` order, row 0 first
    bool half = false;          // store as HALF instead of FLOAT
    int origin_x = 0;           // the data window's minimum corner
    int origin_y = 0;
    bool cube_map = false;      // set the envmap attribute to ENVMAP_CUBE
};

void write_map_exr(const std::string& path, const MapFile& map);

// A width x height RGB map whose texel (x, y) is (x, y, 0.5) * scale.
MapFile gradient_map(int width, int height, float scale = 1.0f);

}  // namespace orb::exr::testing
