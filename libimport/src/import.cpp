// Chooses the importer for an input (orb/import/importers.h) and hands it over.
#include "orb/import/import.h"

#include "foreign_formats.h"
#include "importer_entries.h"
#include "orb/import/importers.h"
#include "orb/scene/error.h"

namespace orb {
namespace {

[[noreturn]] void refuse_unsupported(const std::string& source, const std::string& format) {
    throw InputError(source + ": unsupported format (" + format + "); Orb reads " + readable_file_names());
}

// The reader for an input no --from names. A name whose extension decides
// (.gltf, .glb, .ply, .orb) picks its reader, even when the content is too
// broken to recognise (that reader's error is the useful one), unless the
// content is a format Orb does not read. Otherwise the content decides, and
// text no importer recognises goes to the fallback reader (.scn) unless its
// content or its name says it is a format Orb does not read.
const SceneImporter& choose_importer(std::string_view bytes, const std::string& source) {
    const SceneImporter* recognised = nullptr;
    const SceneImporter* fallback = nullptr;
    for (const SceneImporter& importer : scene_importers()) {
        const ContentMatch match = importer.recognise(bytes);
        if (match == ContentMatch::Yes) {
            recognised = &importer;
            break;
        }
        if (match == ContentMatch::Fallback && !fallback) fallback = &importer;
    }
    const bool unrecognised = !recognised && fallback;
    if (unrecognised) {
        const std::string foreign = detail::foreign_format_by_content(bytes);
        if (!foreign.empty()) refuse_unsupported(source, foreign);
    }
    if (const SceneImporter* named = scene_importer_for_path(source)) return *named;
    if (recognised) return *recognised;
    if (fallback) {
        const std::string foreign = detail::foreign_format_by_extension(source);
        if (!foreign.empty()) refuse_unsupported(source, foreign);
        return *fallback;
    }
    throw InputError(source + ": empty input, expected a scene (Orb reads " + readable_file_names() + ")");
}

const SceneImporter& chosen_importer(const std::string& format) {
    if (const SceneImporter* importer = find_scene_importer(format)) return *importer;
    std::string words;
    for (const std::string& word : scene_format_words()) {
        if (!words.empty()) words += ", ";
        words += word;
    }
    throw InputError("unknown scene format \"" + format + "\"; the formats are " + words);
}

}  // namespace

ImportResult import_scene(std::string_view bytes, const std::string& source, const std::string& base_dir,
                          const ImportOptions& options) {
    const SceneImporter& importer =
        options.format.empty() ? choose_importer(bytes, source) : chosen_importer(options.format);
    ImporterOutput output = importer.open_frames ? detail::read_chosen_frame(importer, bytes, source, options)
                                                 : importer.read(bytes, source, base_dir, options);
    ImportResult& result = output.imported;
    result.format = importer.name;
    std::string& no_spheres = output.no_spheres;  // why the scene has no sphere, when it has none
    if (no_spheres.empty() && result.scene.spheres.empty()) no_spheres = importer.no_spheres;
    if (!no_spheres.empty()) {
        if (!options.allow_empty)
            throw InputError(source + ": no spheres: " + no_spheres + "; --allow-empty accepts a scene without spheres");
        result.notices.push_back(source + ": no spheres: " + no_spheres);
    }
    return std::move(result);
}

}  // namespace orb
