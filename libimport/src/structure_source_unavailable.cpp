// Fuzz builds only (ORB_FUZZ, clang): gemmi 0.5.7's CIF document types do not
// compile with clang and libstdc++ in C++20 (a vector of a type still being
// defined), so these builds read no PDB or mmCIF and say so. The ordinary
// (gcc) build reads them through structure_source.cpp, and the fuzz corpus
// replay test runs the PDB and mmCIF inputs there.
#include "orb/scene/error.h"
#include "structure_source.h"

namespace orb::molecular {

std::unique_ptr<FrameSource> open_structure(std::string_view, const std::string& source, std::string_view format,
                                            const MolecularImportOptions&) {
    throw InputError(source + ": " + std::string(format) +
                     " is not read in this build (a clang fuzz build: gemmi 0.5.7 does not compile with clang in C++20)");
}

}  // namespace orb::molecular
