// The property every glTF fuzz input must have, shared by the libFuzzer
// target (tests/fuzz/fuzz_gltf.cpp) and the replay of its regression corpus
// (tests/fuzz/corpus/fuzz_gltf/) in ordinary builds.
#pragma once

#include <string_view>

namespace orb::fuzz {

// import_gltf either throws InputError or returns a scene that round-trips
// through the canonical JSON and can be evaluated at any time. Throws
// std::logic_error when a property is broken. No external file is read.
void check_gltf_input(std::string_view bytes);

}  // namespace orb::fuzz
