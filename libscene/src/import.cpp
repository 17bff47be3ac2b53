// Recognises a scene by its content and hands it to the right importer.
#include "orb/scene/import.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <filesystem>

#include "foreign_formats.h"
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

// SmallptGPU's .scn has no magic number, but its first word is always "camera".
bool starts_like_scn(std::string_view bytes) {
    const std::string_view text = skip_bom_and_space(bytes);
    return text.starts_with("camera") && (text.size() == 6 || std::isspace(static_cast<unsigned char>(text[6])));
}

[[noreturn]] void refuse_unsupported(const std::string& source, const std::string& format) {
    throw InputError(source + ": unsupported format (" + format + "); Orb reads .scn, .gltf/.glb, .ply, .json, .orb");
}

// The reader for an input no --from names. Content that is one of Orb's
// formats decides; a name's extension only settles what content cannot: a
// broken .gltf goes to the glTF reader (whose error is the useful one), and
// text that is not Orb's goes to the .scn reader unless its content or its
// name says it is a format Orb does not read.
SceneFormat choose_format(std::string_view bytes, const std::string& source) {
    const SceneFormat detected = detect_scene_format(bytes);
    const bool unrecognised = detected == SceneFormat::Scn && !starts_like_scn(bytes);
    if (unrecognised) {
        const std::string foreign = detail::foreign_format_by_content(bytes);
        if (!foreign.empty()) refuse_unsupported(source, foreign);
    }
    const SceneFormat named = scene_format_from_extension(source);
    if (named != SceneFormat::Unknown) return named;
    if (unrecognised) {
        const std::string foreign = detail::foreign_format_by_extension(source);
        if (!foreign.empty()) refuse_unsupported(source, foreign);
    }
    return detected;
}

// Why a scene of any format has no sphere, for the error that refuses it.
std::string why_no_spheres(SceneFormat format) {
    switch (format) {
        case SceneFormat::Scn: return "it lists none (size 0)";
        case SceneFormat::OrbJson: return "its \"spheres\" list is empty";
        default: return "it holds none";
    }
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

SceneFormat scene_format_from_extension(const std::string& path) {
    const std::string extension = std::filesystem::path(path).extension().string();
    if (extension == ".gltf" || extension == ".glb") return SceneFormat::GltfJson;  // the reader tells the two apart
    if (extension == ".ply") return SceneFormat::Ply;
    if (extension == ".orb") return SceneFormat::OrbBinary;
    return SceneFormat::Unknown;
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
    const SceneFormat format = options.format == SceneFormat::Unknown ? choose_format(bytes, source) : options.format;
    ImportResult result;
    std::string no_spheres;  // why the scene has no sphere, when it has none
    switch (format) {
        case SceneFormat::OrbJson: result.scene = load_scene_json(bytes, source); break;
        case SceneFormat::Scn: result.scene = parse_scn(bytes, source); break;
        case SceneFormat::GltfJson:
        case SceneFormat::Glb: {
            GltfImportResult gltf = import_gltf(bytes, source, base_dir, options.gltf);
            result = {std::move(gltf.scene), std::move(gltf.warnings), std::move(gltf.notices)};
            no_spheres = std::move(gltf.no_spheres);
            break;
        }
        case SceneFormat::Ply: {
            PlyImportResult ply = import_ply(bytes, source, options.ply);
            result = {std::move(ply.scene), std::move(ply.warnings), std::move(ply.notices)};
            no_spheres = std::move(ply.no_spheres);
            break;
        }
        case SceneFormat::OrbBinary: result.scene = load_scene_binary(bytes, source); break;
        case SceneFormat::Unknown:
            throw InputError(source + ": empty input, expected a scene (Orb JSON, .scn, .gltf, .glb or .ply)");
    }
    if (no_spheres.empty() && result.scene.spheres.empty()) no_spheres = why_no_spheres(format);
    if (!no_spheres.empty()) {
        if (!options.allow_empty)
            throw InputError(source + ": no spheres: " + no_spheres + "; --allow-empty accepts a scene without spheres");
        result.notices.push_back(source + ": no spheres: " + no_spheres);
    }
    return result;
}

}  // namespace orb
