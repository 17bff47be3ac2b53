// libFuzzer target for the molecular readers: PDB and mmCIF (gemmi), XYZ,
// LAMMPS dump and .gro (built with -DORB_FUZZ=ON and clang).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    orb::fuzz::check_molecular_input(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
