// PLY point cloud -> scene: the header, the vertex columns, the scene around them.
#include <string>

#include "orb/scene/error.h"
#include "orb/import/ply.h"
#include "orb/scene/scene_json.h"
#include "ply_header.h"
#include "ply_read.h"
#include "ply_scene.h"
#include "ply_skipped.h"

namespace orb {

bool has_ply_magic(std::string_view bytes) { return bytes.starts_with("ply\n") || bytes.starts_with("ply\r\n"); }

PlyImportResult import_ply(std::string_view bytes, const std::string& source, const PlyImportOptions& options) {
    if (!has_ply_magic(bytes))
        throw InputError(source + ":1: not a PLY file (it must start with the line \"ply\")");
    const ply::Header header = ply::parse_header(bytes, source);
    ply::VertexColumns columns;
    try {
        columns = ply::read_vertices(bytes, header, source);
    } catch (const InputError& e) {
        // A header line read as a comment may be a misspelt keyword ("proprety float z").
        const std::string note = ply::unknown_lines_note(header);
        if (note.empty()) throw;
        throw InputError(std::string(e.what()) + " (" + note + ")");
    }
    PlyImportResult result;
    if (const std::string note = ply::unknown_lines_note(header); !note.empty())
        result.notices.push_back(source + ": header " + note);
    result.warnings = ply::skipped_warnings(header, columns, source);
    for (std::string& warning : ply::keep_usable_properties(columns.properties, source))
        result.warnings.push_back(std::move(warning));
    if (!columns.properties.empty()) {
        std::vector<std::string> names;
        for (const SphereProperty& property : columns.properties) names.push_back(property.name);
        result.notices.push_back(source + ": vertex properties kept as sphere properties (for --color-by, --radius-by): " +
                                 ply::compact_names(names));
    }
    if (columns.centers.empty()) {
        // No cloud to frame or light: the scene's defaults, no sphere.
        result.no_spheres = ply::why_no_points(header);
        return result;
    }
    result.scene = ply::cloud_scene(std::move(columns), options, source);
    validate_scene(result.scene, source);  // the rules every scene obeys, whoever built it
    return result;
}

}  // namespace orb
