// libFuzzer target for the molecular readers: XYZ, LAMMPS dump and .gro
// (built with -DORB_FUZZ=ON and clang). PDB and mmCIF are not read in a
// clang build (gemmi 0.5.7 does not compile there); the corpus replay test
// of the ordinary build runs this target's inputs through them too.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    orb::fuzz::check_molecular_input(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
