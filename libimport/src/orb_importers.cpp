// Orb's own forms, JSON and binary (libscene), as importers
// (orb/import/importers.h), so that every tool reads them as it reads the others.
#include "importer_entries.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"
#include "text_start.h"

namespace orb::detail {
namespace {

// Any JSON text that glTF (checked first) did not take.
ContentMatch recognise_orb_json(std::string_view bytes) {
    return skip_bom_and_space(bytes).starts_with('{') ? ContentMatch::Yes : ContentMatch::No;
}

ImporterOutput read_orb_json(std::string_view bytes, const std::string& source, const std::string&, const ImportOptions&) {
    return scene_only(load_scene_json(bytes, source));
}

ContentMatch recognise_orb_binary(std::string_view bytes) {
    return has_scene_binary_magic(bytes) ? ContentMatch::Yes : ContentMatch::No;
}

ImporterOutput read_orb_binary(std::string_view bytes, const std::string& source, const std::string&,
                               const ImportOptions&) {
    return scene_only(load_scene_binary(bytes, source));
}

}  // namespace

const SceneImporter& orb_json_importer() {
    static const SceneImporter importer{
        .name = "orb",
        .aliases = {"json"},
        .description = "the canonical Orb scene, JSON (docs/scene-format.md)",
        .extensions = {".json"},
        .recognise = recognise_orb_json,
        .read = read_orb_json,
        .no_spheres = "its \"spheres\" list is empty"};
    return importer;
}

const SceneImporter& orb_binary_importer() {
    static const SceneImporter importer{
        .name = "orb-binary",
        .description = "the binary Orb scene, for millions of spheres (docs/scene-format.md#binary-form)",
        .extensions = {".orb"},
        .extension_decides = true,
        .recognise = recognise_orb_binary,
        .read = read_orb_binary};
    return importer;
}

}  // namespace orb::detail
