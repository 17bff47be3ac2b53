// The table of scene importers (orb/scene/importers.h). Each entry adapts its
// reader to the common signature; recognising and choosing are in import.cpp.
#include "orb/scene/importers.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>

#include "import_option_groups.h"
#include "orb/scene/error.h"
#include "orb/scene/gltf.h"
#include "orb/scene/molecular.h"
#include "orb/scene/ply.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"
#include "orb/scene/scn.h"
#include "text_start.h"

namespace orb {
namespace {

// A reader that gives only a scene.
ImporterOutput scene_only(Scene scene) {
    ImporterOutput output;
    output.imported.scene = std::move(scene);
    return output;
}

// A reader that also says what it lost, added, and why it found no sphere (glTF, PLY).
template <typename ReaderResult>
ImporterOutput with_diagnostics(ReaderResult read) {
    ImporterOutput output = scene_only(std::move(read.scene));
    output.imported.warnings = std::move(read.warnings);
    output.imported.notices = std::move(read.notices);
    output.no_spheres = std::move(read.no_spheres);
    return output;
}

// SmallptGPU's .scn has no magic number, but its first word is always
// "camera"; any other text may still be one (its reader then says what it
// expected), unless its content or name shows another format.
ContentMatch recognise_scn(std::string_view bytes) {
    const std::string_view text = detail::skip_bom_and_space(bytes);
    if (text.empty()) return ContentMatch::No;
    const bool camera = text.starts_with("camera") && (text.size() == 6 || std::isspace(static_cast<unsigned char>(text[6])));
    return camera ? ContentMatch::Yes : ContentMatch::Fallback;
}

ImporterOutput read_scn(std::string_view bytes, const std::string& source, const std::string&, const ImportOptions&) {
    return scene_only(parse_scn(bytes, source));
}

// GLB starts with the bytes "glTF". Both JSON formats start with '{': a glTF
// asset has the required "asset" object and no Orb "format". Malformed JSON
// is guessed, so that the right reader reports the syntax error.
ContentMatch recognise_gltf(std::string_view bytes) {
    if (bytes.starts_with("glTF")) return ContentMatch::Yes;
    const std::string_view text = detail::skip_bom_and_space(bytes);
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
    return with_diagnostics(import_gltf(bytes, source, base_dir, options.gltf));  // tells .gltf and .glb apart
}

ContentMatch recognise_ply(std::string_view bytes) { return has_ply_magic(bytes) ? ContentMatch::Yes : ContentMatch::No; }

ImporterOutput read_ply(std::string_view bytes, const std::string& source, const std::string&,
                        const ImportOptions& options) {
    return with_diagnostics(import_ply(bytes, source, options.ply));
}

// Any JSON text that glTF (checked first) did not take.
ContentMatch recognise_orb_json(std::string_view bytes) {
    return detail::skip_bom_and_space(bytes).starts_with('{') ? ContentMatch::Yes : ContentMatch::No;
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

// The molecular and particle formats (orb/scene/molecular.h): orb-import
// writes one frame of them (--frame, the first by default); orb-render reads
// them frame by frame from the file instead (orb/request/scene_input.h).
ImporterOutput molecular_frame(const FrameSource& source_frames, const std::string& source, long frame);

ImporterOutput read_molecular(std::string_view format, std::string_view bytes, const std::string& source,
                              const ImportOptions& options) {
    const std::unique_ptr<FrameSource> frames = open_molecular_bytes(bytes, source, format, options.molecular);
    return molecular_frame(*frames, source, options.molecular.frame);
}

// Frame `frame` (from 1) of a molecular file or series, with what reading it lost and how many frames there are.
ImporterOutput molecular_frame(const FrameSource& source_frames, const std::string& source, long frame) {
    const FrameSource* frames = &source_frames;
    const std::size_t count = frames->frame_count();
    if (frame < 1 || static_cast<std::size_t>(frame) > count)
        throw InputError(source + ": has " + std::to_string(count) + (count == 1 ? " frame" : " frames") +
                         " (1-" + std::to_string(count) + "); there is no frame " + std::to_string(frame));
    ImporterOutput output = scene_only(frames->frame(static_cast<std::size_t>(frame - 1)));
    validate_scene(output.imported.scene, source);  // the rules every scene obeys, whoever built it
    output.imported.warnings = frames->warnings();
    if (count > 1)
        output.imported.notices.push_back(source + ": holds " + std::to_string(count) + " frames; this is frame " +
                                          std::to_string(frame) + " (orb-render --frames 1-" + std::to_string(count) +
                                          " renders them all from the file)");
    return output;
}

template <std::size_t N>
struct FormatName {
    char text[N];
    constexpr FormatName(const char (&name)[N]) { std::copy_n(name, N, text); }
    constexpr std::string_view view() const { return {text, N - 1}; }
};

template <FormatName Name>
ContentMatch recognise_molecular(std::string_view bytes) {
    return recognise_molecular_file(bytes.substr(0, 65536), "") == Name.view() ? ContentMatch::Yes : ContentMatch::No;
}

template <FormatName Name>
ImporterOutput read_molecular_as(std::string_view bytes, const std::string& source, const std::string&,
                                 const ImportOptions& options) {
    return read_molecular(Name.view(), bytes, source, options);
}

const std::vector<SceneImporter>& table() {
    static const std::vector<SceneImporter> importers{
        {.name = "scn",
         .description = "SmallptGPU scene: text whose first word is camera (docs/scn-format.md)",
         .extensions = {".scn"},
         .recognise = recognise_scn,
         .read = read_scn,
         .no_spheres = "it lists none (size 0)"},
        {.name = "gltf",
         .aliases = {"glb"},
         .description = "glTF 2.0 asset, JSON or binary: its spheres, lights, camera, animation (docs/gltf.md)",
         .extensions = {".gltf", ".glb"},
         .extension_decides = true,
         .recognise = recognise_gltf,
         .read = read_gltf,
         .options = &detail::kGltfOptions},
        {.name = "ply",
         .description = "PLY point cloud, ASCII or binary: one sphere per vertex",
         .extensions = {".ply"},
         .extension_decides = true,
         .recognise = recognise_ply,
         .read = read_ply,
         .options = &detail::kPlyOptions},
        {.name = "orb",
         .aliases = {"json"},
         .description = "the canonical Orb scene, JSON (docs/scene-format.md)",
         .extensions = {".json"},
         .recognise = recognise_orb_json,
         .read = read_orb_json,
         .no_spheres = "its \"spheres\" list is empty"},
        {.name = "orb-binary",
         .description = "the binary Orb scene, for millions of spheres (docs/scene-format.md#binary-form)",
         .extensions = {".orb"},
         .extension_decides = true,
         .recognise = recognise_orb_binary,
         .read = read_orb_binary},
        {.name = "pdb",
         .aliases = {"ent"},
         .description = "Protein Data Bank file, through gemmi: an atom per sphere, its models as frames",
         .extensions = {".pdb", ".ent"},
         .extension_decides = true,
         .recognise = recognise_molecular<"pdb">,
         .read = read_molecular_as<"pdb">,
         .options = &detail::kMolecularOptions},
        {.name = "mmcif",
         .aliases = {"cif"},
         .description = "PDBx/mmCIF file, through gemmi: an atom per sphere, its models as frames",
         .extensions = {".cif", ".mmcif"},
         .extension_decides = true,
         .recognise = recognise_molecular<"mmcif">,
         .read = read_molecular_as<"mmcif">,
         .options = &detail::kMolecularOptions},
        {.name = "xyz",
         .aliases = {"extxyz"},
         .description = "XYZ or extended XYZ: an atom per sphere, each frame of a trajectory a frame",
         .extensions = {".xyz", ".extxyz"},
         .extension_decides = true,
         .recognise = recognise_molecular<"xyz">,
         .read = read_molecular_as<"xyz">,
         .options = &detail::kMolecularOptions},
        {.name = "lammps-dump",
         .aliases = {"lammpstrj"},
         .description = "LAMMPS text dump (atom or custom style): a particle per sphere, each timestep a frame",
         .extensions = {".lammpstrj", ".dump"},
         .extension_decides = true,
         .recognise = recognise_molecular<"lammps-dump">,
         .read = read_molecular_as<"lammps-dump">,
         .options = &detail::kMolecularOptions},
        {.name = "gro",
         .description = "GROMACS .gro: an atom per sphere, each frame a frame (nm become angstrom)",
         .extensions = {".gro"},
         .extension_decides = true,
         .recognise = recognise_molecular<"gro">,
         .read = read_molecular_as<"gro">,
         .options = &detail::kMolecularOptions},
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

ImportResult import_molecular_series(const std::string& pattern, const ImportOptions& options) {
    const std::unique_ptr<FrameSource> frames = open_molecular_series(pattern, options.molecular);
    if (!options.format.empty()) {  // --from: the importer's name or an alias ("lammpstrj")
        const SceneImporter* chosen = find_scene_importer(options.format);
        if (!chosen || chosen->name != frames->format())
            throw InputError(pattern + ": --from " + options.format + ", but the series is " +
                             std::string(frames->format()));
    }
    ImportResult result = molecular_frame(*frames, pattern, options.molecular.frame).imported;
    result.format = frames->format();
    return result;
}

}  // namespace orb
