// PLY point clouds (ASCII, binary little- and big-endian) -> a scene of
// spheres: one sphere per vertex, shared diffuse materials per colour, an
// automatic camera and default lights. Every rule is in docs/orb-import.md.
#pragma once

#include <string>
#include <string_view>

#include "orb/scene/scene.h"

namespace orb {

struct PlyImportOptions {
    // Radius of vertices without a `radius` (or `scale`) property, in scene
    // units; <= 0: half the typical spacing of the cloud (docs/orb-import.md).
    double radius = 0.0;
};

// `source` names the input in messages. Throws InputError naming the header
// line ("cloud.ply:4: ...") or the vertex ("cloud.ply: vertex 17: ...").
Scene import_ply(std::string_view bytes, const std::string& source, const PlyImportOptions& options = {});

// True when the bytes start with the PLY magic line ("ply" + LF or CR LF).
bool has_ply_magic(std::string_view bytes);

}  // namespace orb
