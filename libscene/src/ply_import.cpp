// PLY point cloud -> scene: the header, the vertex columns, the scene around them.
#include <string>

#include "orb/scene/error.h"
#include "orb/scene/ply.h"
#include "orb/scene/scene_json.h"
#include "ply_header.h"
#include "ply_read.h"
#include "ply_scene.h"

namespace orb {

bool has_ply_magic(std::string_view bytes) { return bytes.starts_with("ply\n") || bytes.starts_with("ply\r\n"); }

Scene import_ply(std::string_view bytes, const std::string& source, const PlyImportOptions& options) {
    if (!has_ply_magic(bytes))
        throw InputError(source + ":1: not a PLY file (it must start with the line \"ply\")");
    const ply::Header header = ply::parse_header(bytes, source);
    ply::VertexColumns columns = ply::read_vertices(bytes, header, source);
    if (columns.centers.empty()) throw InputError(source + ": the 'vertex' element is empty, there is nothing to render");
    Scene scene = ply::cloud_scene(std::move(columns), options, source);
    validate_scene(scene, source);  // the rules every scene obeys, whoever built it
    return scene;
}

}  // namespace orb
