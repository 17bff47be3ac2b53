// What a PLY import reads past, in words: the warnings that name every
// vertex property, element and byte Orb does not use, and the reason a file
// without points gives no sphere.
#pragma once

#include <string>
#include <vector>

#include "ply_header.h"
#include "ply_read.h"

namespace orb::ply {

// "cloud.ply: ignored vertex properties: nx, ny, nz, s, t",
// "cloud.ply: ignored elements: face (16301 rows)", and bytes after the
// last element; none when everything is read.
std::vector<std::string> skipped_warnings(const Header& header, const VertexColumns& columns,
                                          const std::string& source);

// "its 'vertex' element has 0 rows" or "it has no 'vertex' element".
std::string why_no_points(const Header& header);

// Names with runs of numbered ones shortened: f_rest_0 ... f_rest_44 become
// "f_rest_0..44"; the order is kept.
std::string compact_names(const std::vector<std::string>& names);

}  // namespace orb::ply
