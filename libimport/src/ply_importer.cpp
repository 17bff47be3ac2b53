// PLY point clouds as an importer (orb/import/importers.h).
#include "import_option_groups.h"
#include "importer_entries.h"
#include "orb/import/ply.h"

namespace orb::detail {
namespace {

ContentMatch recognise_ply(std::string_view bytes) { return has_ply_magic(bytes) ? ContentMatch::Yes : ContentMatch::No; }

ImporterOutput read_ply(std::string_view bytes, const std::string& source, const std::string&,
                        const ImportOptions& options) {
    return with_diagnostics(import_ply(bytes, source, options.of<PlyImportOptions>()));
}

}  // namespace

const SceneImporter& ply_importer() {
    static const SceneImporter importer{
        .name = "ply",
        .description = "PLY point cloud, ASCII or binary: one sphere per vertex",
        .extensions = {".ply"},
        .extension_decides = true,
        .recognise = recognise_ply,
        .read = read_ply,
        .options = &kPlyOptions};
    return importer;
}

}  // namespace orb::detail
