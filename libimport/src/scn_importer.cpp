// SmallptGPU's .scn as an importer (orb/import/importers.h).
#include <cctype>

#include "importer_entries.h"
#include "orb/import/scn.h"
#include "text_start.h"

namespace orb::detail {
namespace {

// SmallptGPU's .scn has no magic number, but its first word is always
// "camera"; any other text may still be one (its reader then says what it
// expected), unless its content or name shows another format.
ContentMatch recognise_scn(std::string_view bytes) {
    const std::string_view text = skip_bom_and_space(bytes);
    if (text.empty()) return ContentMatch::No;
    const bool camera = text.starts_with("camera") && (text.size() == 6 || std::isspace(static_cast<unsigned char>(text[6])));
    return camera ? ContentMatch::Yes : ContentMatch::Fallback;
}

ImporterOutput read_scn(std::string_view bytes, const std::string& source, const std::string&, const ImportOptions&) {
    return scene_only(parse_scn(bytes, source));
}

}  // namespace

const SceneImporter& scn_importer() {
    static const SceneImporter importer{
        .name = "scn",
        .description = "SmallptGPU scene: text whose first word is camera (docs/scn-format.md)",
        .extensions = {".scn"},
        .recognise = recognise_scn,
        .read = read_scn,
        .no_spheres = "it lists none (size 0)"};
    return importer;
}

}  // namespace orb::detail
