// Recognises a scene by its content and hands it to the right importer.
#include "orb/scene/import.h"

#include <nlohmann/json.hpp>

#include "orb/scene/error.h"
#include "orb/scene/ply.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"
#include "orb/scene/scn.h"

namespace orb {
namespace {

std::string_view skip_bom_and_space(std::string_view bytes) {
    if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
    while (!bytes.empty() && (bytes.front() == ' ' || bytes.front() == '\t' || bytes.front() == '\r' ||
                              bytes.front() == '\n'))
        bytes.remove_prefix(1);
    return bytes;
}

}  // namespace

SceneFormat detect_scene_format(std::string_view bytes) {
    if (bytes.substr(0, 4) == "glTF") return SceneFormat::Glb;
    if (has_ply_magic(bytes)) return SceneFormat::Ply;
    if (has_scene_binary_magic(bytes)) return SceneFormat::OrbBinary;
    std::string_view text = skip_bom_and_space(bytes);
    if (text.empty()) return SceneFormat::Unknown;
    if (text.front() == '{') {
        // Both JSON formats start with '{': an Orb scene names its format, a
        // glTF asset has the required "asset" object.
        auto document = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
        if (!document.is_discarded() && document.is_object()) {
            if (document.contains("asset") && !document.contains("format")) return SceneFormat::GltfJson;
            return SceneFormat::OrbJson;
        }
        // Malformed JSON: guess, so that the right reader reports the syntax error.
        if (text.find("\"asset\"") != std::string_view::npos && text.find("\"orb-scene\"") == std::string_view::npos)
            return SceneFormat::GltfJson;
        return SceneFormat::OrbJson;
    }
    return SceneFormat::Scn;
}

SceneFormat scene_format_from_name(const std::string& name) {
    if (name == "orb" || name == "json") return SceneFormat::OrbJson;
    if (name == "scn") return SceneFormat::Scn;
    if (name == "gltf") return SceneFormat::GltfJson;
    if (name == "glb") return SceneFormat::Glb;
    if (name == "ply") return SceneFormat::Ply;
    if (name == "orb-binary") return SceneFormat::OrbBinary;
    return SceneFormat::Unknown;
}

const char* scene_format_name(SceneFormat format) {
    switch (format) {
        case SceneFormat::OrbJson: return "orb";
        case SceneFormat::Scn: return "scn";
        case SceneFormat::GltfJson: return "gltf";
        case SceneFormat::Glb: return "glb";
        case SceneFormat::Ply: return "ply";
        case SceneFormat::OrbBinary: return "orb-binary";
        case SceneFormat::Unknown: break;
    }
    return "unknown";
}

ImportResult import_scene(std::string_view bytes, const std::string& source, const std::string& base_dir,
                          const ImportOptions& options) {
    SceneFormat format = options.format;
    if (format == SceneFormat::Unknown) format = detect_scene_format(bytes);
    switch (format) {
        case SceneFormat::OrbJson: return {load_scene_json(bytes, source), {}, {}};
        case SceneFormat::Scn: return {parse_scn(bytes, source), {}, {}};
        case SceneFormat::GltfJson:
        case SceneFormat::Glb: {
            GltfImportResult result = import_gltf(bytes, source, base_dir, options.gltf);
            return {std::move(result.scene), std::move(result.warnings), std::move(result.notices)};
        }
        case SceneFormat::Ply: return {import_ply(bytes, source, options.ply), {}, {}};
        case SceneFormat::OrbBinary: return {load_scene_binary(bytes, source), {}, {}};
        case SceneFormat::Unknown: break;
    }
    throw InputError(source + ": empty input, expected a scene (Orb JSON, .scn, .gltf, .glb or .ply)");
}

}  // namespace orb
