// The scene importers, one entry each: what the format is called, how an
// input is recognised (content, file name), the function that reads it, the
// options that apply to it, and a line that describes it. import_scene
// chooses from this table; orb-import's --from and --list-formats, the
// refusal of formats Orb does not read, the formats read frame by frame
// (orb/import/molecular.h) and docs/orb-import.md read it too. Each entry
// lives beside its reader (libimport/src/*_importer.cpp, *_read.cpp), which
// also owns its recognising and its option group: adding a format is its
// file and one line in libimport/src/importers.cpp.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "orb/import/import.h"

namespace CLI {
class App;
}

namespace orb {

class FrameSource;              // orb/import/molecular.h
struct MolecularImportOptions;  // orb/import/molecular.h

// An importer's command-line options (or a family's that reads with the same
// ones: the molecular readers), declared beside its reader
// (libimport/src/*_options.cpp). Every tool that reads a scene (orb-import,
// orb-render, orb-frames --scene, and orb-farm through orb-render) adds every
// group (orb/cli/scene_reading.h), so one option has one name and one
// meaning everywhere.
struct ImportOptionGroup {
    // The group's heading in --help ("PLY input"), also --list-formats' OPTIONS column.
    std::string_view heading{};
    // Adds the group's options to a tool's command line (CLI11), writing into
    // `options` (its struct of them: options.of<PlyImportOptions>()); CLI11's
    // checks refuse a bad value as a usage error.
    void (*add)(CLI::App& app, ImportOptions& options) = nullptr;
};

// How sure an importer is, from the bytes alone, that an input is its format.
enum class ContentMatch {
    No,        // not this format (or nothing to read: empty text)
    Fallback,  // could be: the reader to try when no importer says Yes (the .scn reader takes any text)
    Yes,       // this format's magic number or structure
};

// What an importer's read function hands back.
struct ImporterOutput {
    ImportResult imported;
    // Why the scene has no sphere, when it has none and the reader knows
    // better than "it holds none" ("its 'vertex' element has 0 rows").
    std::string no_spheres;
};

// What a format read frame by frame opens: one input (`bytes`, or the file
// `paths[0]`), or the files of a numbered series one after another.
struct FrameInput {
    std::vector<std::string> paths;  // empty: read `bytes`
    std::string_view bytes;          // must outlive the source
    std::string source;              // names the input in messages
};

struct SceneImporter {
    std::string_view name{};                  // --from's word, the name in messages and listings: "ply"
    std::vector<std::string_view> aliases{}; // other words --from takes for it: "json", "glb"
    std::string_view description{};           // one line, for orb-import --list-formats
    // The file name endings its files have (lowercase, compared in any case),
    // listed in messages ("Orb reads .scn, .gltf/.glb, ...").
    std::vector<std::string_view> extensions{};
    // Whether such a name sends an input here even when no importer
    // recognises its content, so that a broken file gets this reader's error.
    bool extension_decides = false;
    // Checked in table order; the first Yes wins (so a more specific format
    // comes before one that takes what it leaves: glTF JSON before Orb JSON).
    ContentMatch (*recognise)(std::string_view bytes) = nullptr;
    // Reads the input; throws InputError naming the source and the place.
    // Null for a format read frame by frame (open_frames): import_scene then
    // reads the frame MolecularImportOptions::frame names.
    ImporterOutput (*read)(std::string_view bytes, const std::string& source, const std::string& base_dir,
                           const ImportOptions& options) = nullptr;
    // The formats whose files hold frames (molecular and particle
    // trajectories): opens them to be read one frame at a time. Null for a
    // format that is one scene. Throws InputError.
    std::unique_ptr<FrameSource> (*open_frames)(const FrameInput& input, const MolecularImportOptions& options) = nullptr;
    // Whether a numbered series of its files ("dump.*.lammpstrj") is one trajectory.
    bool reads_series = false;
    // The options that apply to this format only; null when none do.
    const ImportOptionGroup* options = nullptr;
    // Why a scene of this format has no sphere, when the reader does not say.
    std::string_view no_spheres = "it holds none";
};

// Every importer, in the order their content is checked.
std::span<const SceneImporter> scene_importers();

// Every importer's option group, each once, in the table's order.
std::vector<const ImportOptionGroup*> import_option_groups();

// The importer `name` names (its name or an alias); null for any other word.
const SceneImporter* find_scene_importer(std::string_view name);

// The importer whose extension `path` has and decides by (.gltf, .glb, .ply, .orb); null for any other.
const SceneImporter* scene_importer_for_path(const std::string& path);

// Whether `path`'s extension is one an importer lists (any case).
bool is_importer_extension(const std::string& path);

// The first importer that says Yes to the bytes; null when none does.
const SceneImporter* recognise_scene(std::string_view bytes);

// The importer read frame by frame that `name` names; null for any other word.
const SceneImporter* find_frame_importer(std::string_view name);

// "orb, json, scn, gltf, glb, ply, orb-binary": every word --from takes, in table order.
std::vector<std::string> scene_format_words();

// ".scn, .gltf/.glb, .ply, .json, .orb": the file names Orb reads, for messages.
std::string readable_file_names();

}  // namespace orb
