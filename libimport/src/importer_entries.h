// Private: the importers' entries (orb/import/importers.h SceneImporter),
// each defined beside its reader, and what adapting a reader to the entry's
// signature takes. libimport/src/importers.cpp lists them in table order.
#pragma once

#include <utility>

#include "orb/import/importers.h"

namespace orb::detail {

const SceneImporter& scn_importer();         // scn_importer.cpp
const SceneImporter& gltf_importer();        // gltf_importer.cpp
const SceneImporter& ply_importer();         // ply_importer.cpp
const SceneImporter& orb_json_importer();    // orb_importers.cpp
const SceneImporter& orb_binary_importer();  // orb_importers.cpp
const SceneImporter& pdb_importer();         // structure_importers.cpp
const SceneImporter& mmcif_importer();       // structure_importers.cpp
const SceneImporter& xyz_importer();         // xyz_read.cpp
const SceneImporter& lammps_dump_importer(); // lammps_dump_read.cpp
const SceneImporter& gro_importer();         // gro_read.cpp

// A reader that gives only a scene.
inline ImporterOutput scene_only(Scene scene) {
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

// The frame MolecularImportOptions::frame names of an input of a format read
// frame by frame (import_scene's reader for them; molecular_sources.cpp).
ImporterOutput read_chosen_frame(const SceneImporter& importer, std::string_view bytes, const std::string& source,
                                 const ImportOptions& options);

}  // namespace orb::detail
