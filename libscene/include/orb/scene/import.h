// Recognising a scene file by content and importing it into the canonical
// model. The formats are the entries of orb/scene/importers.h.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "orb/scene/gltf.h"
#include "orb/scene/molecular.h"
#include "orb/scene/ply.h"
#include "orb/scene/scene.h"

namespace orb {

struct ImportOptions {
    // A name of an importer (orb/scene/importers.h: "ply", "json", ...);
    // empty: recognise the format by content (and the name's extension).
    std::string format;
    // A scene without spheres is refused, with what was left out and why
    // (an asset of triangle meshes); true accepts it.
    bool allow_empty = false;
    GltfImportOptions gltf;
    PlyImportOptions ply;
    MolecularImportOptions molecular;
};

struct ImportResult {
    Scene scene;
    std::vector<std::string> warnings;  // losses: an error for tools run with --strict
    std::vector<std::string> notices;   // additions, such as glTF's default light: warned about, never fatal
    std::string_view format;            // the name of the importer that read it ("gltf")
};

// `source` names the input in messages (a path, or <stdin>); without a chosen
// format its extension helps to choose one: a .gltf/.glb/.ply/.orb name goes
// to that reader even when the content is too broken to recognise, and a
// format Orb does not read (tri.obj, by content or by name) is refused as
// such. `base_dir` resolves external files (glTF buffers). Throws InputError,
// also for a `format` no importer has.
ImportResult import_scene(std::string_view bytes, const std::string& source, const std::string& base_dir,
                          const ImportOptions& options = {});

// Frame options.molecular.frame of a numbered series of molecular files
// ("dump.*.lammpstrj", orb/scene/molecular.h open_molecular_series), as
// import_scene reads one of a single file. Throws InputError, also when
// options.format is given and the series is another format.
ImportResult import_molecular_series(const std::string& pattern, const ImportOptions& options = {});

}  // namespace orb
