// The pbr albedo table as the kernels hold it (kernels/bsdf_pbr_albedo.cl),
// read back from the embedded kernel text, and its interpolation.
#pragma once

#include <vector>

namespace orb::render::test {

struct PbrAlbedoTable {
    int size = 0;
    double min_roughness = 0;
    double largest_raise = 0;  // stated in the file's header
    std::vector<double> table;    // size x size, rows by roughness
    std::vector<double> average;  // per row
    // The kernels' bilinear interpolation (bsdf_pbr.cl's pbr_layer_albedo), for a rough lobe.
    double interpolate(double cos_o, double roughness) const;
};

const PbrAlbedoTable& pbr_albedo_table();

}  // namespace orb::render::test
