// The binary form of the canonical scene, for scenes of millions of spheres
// (docs/scene-format.md, "Binary form"): a small JSON header with everything
// but the spheres, then the sphere arrays as raw little-endian numbers.
// Lossless: load_scene_binary(write_scene_binary(s)) == s exactly.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "orb/scene/scene.h"

namespace orb {

// Version 2 added the per-sphere attribute arrays (colours, properties) after
// the names; the writer uses it only for a scene that has them and writes
// version 1 otherwise. The reader reads both.
inline constexpr std::uint32_t kSceneBinaryVersion = 2;
// PNG-style: a non-ASCII first byte, then CR LF, ^Z and LF, so that text-mode
// transfers and truncation to 7 bits are caught at the first bytes.
inline constexpr std::string_view kSceneBinaryMagic{"\x89ORB\r\n\x1a\n", 8};

bool has_scene_binary_magic(std::string_view bytes);

std::string write_scene_binary(const Scene& scene);

// Validates exactly as load_scene_json does (validate_scene) plus the
// container's own rules; throws InputError naming `source`.
Scene load_scene_binary(std::string_view bytes, const std::string& source);

}  // namespace orb
