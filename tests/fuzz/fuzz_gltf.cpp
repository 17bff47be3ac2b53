// libFuzzer target for the glTF importer (built with -DORB_FUZZ=ON and clang).
// Seeds: tests/fuzz/corpus/fuzz_gltf/ and the glTF-Validator corpus.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "../gltf/gltf_fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    orb::fuzz::check_gltf_input(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
