// The canonical Orb scene as JSON (docs/scene-format.md, docs/orb-scene.schema.json).
#pragma once

#include <string>
#include <string_view>

#include "orb/scene/scene.h"

namespace orb {

inline constexpr int kSceneFormatVersion = 1;

// Sanity limits a scene must respect (beyond them a file is more likely
// corrupt than intended).
inline constexpr int kMaxImageSide = 65536;
inline constexpr int kMaxSpp = 1 << 24;
inline constexpr int kMaxDepth = 1024;

// Parses and validates; throws InputError naming `source` and the JSON path
// of the first problem ("scene.json: spheres[3].radius: must be > 0, got -2").
Scene load_scene_json(std::string_view text, const std::string& source);

// Stable, diff-friendly output: fixed key order, shortest round-trip numbers,
// so load_scene_json(write_scene_json(s)) == s exactly.
std::string write_scene_json(const Scene& scene);

// Checks a scene built in memory (by an importer) with the same rules the
// loader applies; throws InputError naming `source` and the JSON path.
void validate_scene(const Scene& scene, const std::string& source);

// 64-bit FNV-1a of the canonical JSON, as 16 hex digits: the scene's identity
// for resume and provenance.
std::string scene_content_hash(const Scene& scene);

}  // namespace orb
