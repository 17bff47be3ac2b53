// PDB and mmCIF as importers (orb/import/importers.h), read through gemmi
// (structure_source.h): a file's models are its frames.
#include "import_option_groups.h"
#include "importer_entries.h"
#include "line_reader.h"
#include "orb/import/molecular.h"
#include "structure_source.h"
#include "text_start.h"

namespace orb::detail {
namespace {

// The Protein Data Bank's record names (wwPDB format 3.3) a file starts with.
bool is_pdb_record(std::string_view line) {
    for (std::string_view record : {"HEADER", "OBSLTE", "TITLE ", "SPLIT ", "CAVEAT", "COMPND", "SOURCE", "KEYWDS",
                                    "EXPDTA", "NUMMDL", "MDLTYP", "AUTHOR", "REVDAT", "SPRSDE", "JRNL  ", "REMARK",
                                    "DBREF ", "SEQRES", "CRYST1", "ORIGX1", "SCALE1", "ATOM  ", "HETATM", "MODEL "})
        if (line.starts_with(record)) return true;
    return false;
}

ContentMatch recognise_pdb(std::string_view bytes) {
    const std::string_view text = recognised_head(bytes);
    return !text.empty() && is_pdb_record(first_line(text)) ? ContentMatch::Yes : ContentMatch::No;
}

ContentMatch recognise_mmcif(std::string_view bytes) {
    const std::string_view text = recognised_head(bytes);
    return first_line(text).starts_with("data_") ? ContentMatch::Yes : ContentMatch::No;
}

// PDB and mmCIF files are read whole by gemmi (they are small: a structure,
// an NMR ensemble); gemmi's Structure keeps what it needs of the bytes.
std::unique_ptr<FrameSource> open_structure_frames(std::string_view format, const FrameInput& input,
                                                   const MolecularImportOptions& options) {
    if (input.paths.empty()) return molecular::open_structure(input.bytes, input.source, format, options);
    const std::string bytes = molecular::read_file_range(input.paths.front(), 0, 0);
    return molecular::open_structure(bytes, input.paths.front(), format, options);
}

std::unique_ptr<FrameSource> open_pdb_frames(const FrameInput& input, const MolecularImportOptions& options) {
    return open_structure_frames("pdb", input, options);
}

std::unique_ptr<FrameSource> open_mmcif_frames(const FrameInput& input, const MolecularImportOptions& options) {
    return open_structure_frames("mmcif", input, options);
}

}  // namespace

const SceneImporter& pdb_importer() {
    static const SceneImporter importer{
        .name = "pdb",
        .aliases = {"ent"},
        .description = "Protein Data Bank file, through gemmi: an atom per sphere, its models as frames",
        .extensions = {".pdb", ".ent"},
        .extension_decides = true,
        .recognise = recognise_pdb,
        .open_frames = open_pdb_frames,
        .options = &kMolecularOptions};
    return importer;
}

const SceneImporter& mmcif_importer() {
    static const SceneImporter importer{
        .name = "mmcif",
        .aliases = {"cif"},
        .description = "PDBx/mmCIF file, through gemmi: an atom per sphere, its models as frames",
        .extensions = {".cif", ".mmcif"},
        .extension_decides = true,
        .recognise = recognise_mmcif,
        .open_frames = open_mmcif_frames,
        .options = &kMolecularOptions};
    return importer;
}

}  // namespace orb::detail
