// Walks the data section of a PLY file and keeps what a cloud of spheres
// needs from the `vertex` element; every other element and property is read
// past (lists by their counts), so truncation anywhere is noticed.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "orb/scene/scene.h"
#include "ply_header.h"

namespace orb::ply {

struct VertexColumns {
    std::vector<Vec3> centers;
    std::vector<double> radii;  // empty: the vertices have no radius (or scale)
    std::vector<Vec3> colors;   // empty: no colour; else each component in [0, 1] as stored (sRGB-encoded)
    // Every other single-valued vertex property (normals, intensity, a second
    // colour set, ...), in file order, as numbers (float, as the scene keeps
    // them): the spheres' named properties.
    std::vector<SphereProperty> properties;
    // What was read past, for the warnings: vertex properties that are not
    // read (lists), in file order, and the bytes
    // after the last element (white space after ASCII data not counted).
    std::vector<std::string> unused_properties;
    std::size_t trailing_bytes = 0;
};

// Without a `vertex` element the columns are empty (the data is still walked).
// Throws InputError naming the header line or "vertex N" of the first problem.
VertexColumns read_vertices(std::string_view bytes, const Header& header, const std::string& source);

}  // namespace orb::ply
