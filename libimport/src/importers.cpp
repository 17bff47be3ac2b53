// The table of scene importers (orb/import/importers.h): the entries, each
// defined beside its reader (importer_entries.h), in the order their content
// is checked, and the lookups over them. Choosing is in import.cpp.
#include "orb/import/importers.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "importer_entries.h"

namespace orb {
namespace {

// Every importer, in the order their content is checked: the first Yes wins,
// so a more specific format comes before one that takes what it leaves
// (glTF JSON before Orb JSON, XYZ before .gro).
const std::vector<SceneImporter>& table() {
    static const std::vector<SceneImporter> importers{
        detail::scn_importer(),
        detail::gltf_importer(),
        detail::ply_importer(),
        detail::orb_json_importer(),
        detail::orb_binary_importer(),
        detail::pdb_importer(),
        detail::mmcif_importer(),
        detail::xyz_importer(),
        detail::lammps_dump_importer(),
        detail::gro_importer(),
    };
    return importers;
}

std::string lowercase_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

bool lists_extension(const SceneImporter& importer, const std::string& extension) {
    return std::find(importer.extensions.begin(), importer.extensions.end(), extension) != importer.extensions.end();
}

}  // namespace

std::span<const SceneImporter> scene_importers() { return table(); }

std::vector<const ImportOptionGroup*> import_option_groups() {
    std::vector<const ImportOptionGroup*> groups;
    for (const SceneImporter& importer : table())
        if (importer.options && std::find(groups.begin(), groups.end(), importer.options) == groups.end())
            groups.push_back(importer.options);
    return groups;
}

const SceneImporter* find_scene_importer(std::string_view name) {
    for (const SceneImporter& importer : table())
        if (importer.name == name ||
            std::find(importer.aliases.begin(), importer.aliases.end(), name) != importer.aliases.end())
            return &importer;
    return nullptr;
}

const SceneImporter* scene_importer_for_path(const std::string& path) {
    const std::string extension = lowercase_extension(path);
    for (const SceneImporter& importer : table())
        if (importer.extension_decides && lists_extension(importer, extension)) return &importer;
    return nullptr;
}

bool is_importer_extension(const std::string& path) {
    const std::string extension = lowercase_extension(path);
    return std::any_of(table().begin(), table().end(),
                       [&](const SceneImporter& importer) { return lists_extension(importer, extension); });
}

const SceneImporter* find_frame_importer(std::string_view name) {
    const SceneImporter* importer = find_scene_importer(name);
    return importer && importer->open_frames ? importer : nullptr;
}

const SceneImporter* recognise_scene(std::string_view bytes) {
    for (const SceneImporter& importer : table())
        if (importer.recognise(bytes) == ContentMatch::Yes) return &importer;
    return nullptr;
}

std::vector<std::string> scene_format_words() {
    std::vector<std::string> words;
    for (const SceneImporter& importer : table()) {
        words.emplace_back(importer.name);
        for (std::string_view alias : importer.aliases) words.emplace_back(alias);
    }
    return words;
}

std::string readable_file_names() {
    std::string names;
    for (const SceneImporter& importer : table()) {
        std::string joined;
        for (std::string_view extension : importer.extensions) {
            if (!joined.empty()) joined += '/';
            joined += extension;
        }
        if (joined.empty()) continue;
        if (!names.empty()) names += ", ";
        names += joined;
    }
    return names;
}

}  // namespace orb
