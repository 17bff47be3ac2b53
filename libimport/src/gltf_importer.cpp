// glTF 2.0 as an importer (orb/import/importers.h).
#include <nlohmann/json.hpp>

#include "import_option_groups.h"
#include "importer_entries.h"
#include "orb/import/gltf.h"
#include "text_start.h"

namespace orb::detail {
namespace {

// GLB starts with the bytes "glTF". Both JSON formats start with '{': a glTF
// asset has the required "asset" object and no Orb "format". Malformed JSON
// is guessed, so that the right reader reports the syntax error.
ContentMatch recognise_gltf(std::string_view bytes) {
    if (bytes.starts_with("glTF")) return ContentMatch::Yes;
    const std::string_view text = skip_bom_and_space(bytes);
    if (!text.starts_with('{')) return ContentMatch::No;
    const auto document = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
    if (!document.is_discarded() && document.is_object())
        return document.contains("asset") && !document.contains("format") ? ContentMatch::Yes : ContentMatch::No;
    const bool gltf_like = text.find("\"asset\"") != std::string_view::npos &&
                           text.find("\"orb-scene\"") == std::string_view::npos;
    return gltf_like ? ContentMatch::Yes : ContentMatch::No;
}

ImporterOutput read_gltf(std::string_view bytes, const std::string& source, const std::string& base_dir,
                         const ImportOptions& options) {
    // import_gltf tells .gltf and .glb apart.
    return with_diagnostics(import_gltf(bytes, source, base_dir, options.of<GltfImportOptions>()));
}

}  // namespace

const SceneImporter& gltf_importer() {
    static const SceneImporter importer{
        .name = "gltf",
        .aliases = {"glb"},
        .description = "glTF 2.0 asset, JSON or binary: its spheres, lights, camera, animation (docs/gltf.md)",
        .extensions = {".gltf", ".glb"},
        .extension_decides = true,
        .recognise = recognise_gltf,
        .read = read_gltf,
        .options = &kGltfOptions};
    return importer;
}

}  // namespace orb::detail
