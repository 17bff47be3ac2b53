// Private: PDB and mmCIF files, read by gemmi (Debian's gemmi-dev), as frame
// sources: every model of the file (an NMR ensemble's) is a frame.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "orb/import/molecular.h"

namespace orb::molecular {

// `format` is "pdb" or "mmcif". Throws InputError with gemmi's message (which names the line for PDB).
std::unique_ptr<FrameSource> open_structure(std::string_view bytes, const std::string& source, std::string_view format,
                                            const MolecularImportOptions& options);

}  // namespace orb::molecular
