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

// What the renderer's 32-bit floats can hold (docs/scene-format.md, "Limits").
// Coordinates and lengths up to 1e18 keep every square and product of the
// ray-sphere test (at most 3·(2e18)² ≈ 1.2e37) below float's 3.4e38 and hit
// distances below the kernel's 1e30 "no hit"; positive quantities at least
// 1e-18 keep their squares (1e-36) normal floats rather than zero.
inline constexpr double kMaxSceneMagnitude = 1e18;
inline constexpr double kMinScenePositive = 1e-18;
// Emitted radiance up to 1e12 (several times the sun's) keeps a pixel's sum
// of squared radiance finite in float over kMaxSpp samples even when a path
// gathers light at every one of kMaxDepth bounces: (2·1024·1e12)²·2^24 ≈ 7e37.
inline constexpr double kMaxEmission = 1e12;
// An environment map of up to 2^27 texels (16384 x 8192) takes up to 2.5 GB
// on the device (16 bytes of radiance and pdf, 4 of sampling table per
// texel); a larger one is more likely a mistake than a sky.
inline constexpr long long kMaxEnvironmentTexels = 1LL << 27;

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
// for resume and provenance. When the environment map's texels are attached
// (Environment::image), the hash continues over them (width, height, then
// every float's bits, little-endian), so an edited map that keeps its file
// name is a different scene; tools attach them before hashing. The
// per-sphere colours and properties (Scene::sphere_attributes) are hashed
// as their float bits after the JSON without them (a scene without them
// hashes as it did before they existed), then the texels.
std::string scene_content_hash(const Scene& scene);

}  // namespace orb
