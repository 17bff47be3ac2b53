// PLY point clouds (ASCII, binary little- and big-endian) -> a scene of
// spheres: one sphere per vertex, shared diffuse materials per colour, an
// automatic camera and default lights. Every rule is in docs/orb-import.md.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "orb/scene/scene.h"

namespace orb {

struct PlyImportOptions {
    // Radius of vertices without a `radius` (or `scale`) property, in scene
    // units; <= 0: half the typical spacing of the cloud (docs/orb-import.md).
    double radius = 0.0;
};

struct PlyImportResult {
    Scene scene;
    // What the reader read past and Orb loses: vertex properties it does
    // not read (normals, ...), other elements (faces, ...), data after the
    // last element. Each names the file.
    std::vector<std::string> warnings;
    // What it read differently and loses nothing by: a header line without
    // a PLY keyword, read as a comment.
    std::vector<std::string> notices;
    // Set when the file holds no point: why ("its 'vertex' element has 0
    // rows"); the scene then has no sphere (and no lights), and import_scene
    // refuses it unless allowed.
    std::string no_spheres;
};

// `source` names the input in messages. Throws InputError naming the header
// line ("cloud.ply:4: ...") or the vertex ("cloud.ply: vertex 17: ...").
PlyImportResult import_ply(std::string_view bytes, const std::string& source, const PlyImportOptions& options = {});

// True when the bytes start with the PLY magic line ("ply" + LF or CR LF).
bool has_ply_magic(std::string_view bytes);

}  // namespace orb
