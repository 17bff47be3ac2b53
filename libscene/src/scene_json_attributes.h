// The per-sphere arrays of the canonical scene (orb/scene/sphere_attributes.h)
// in the JSON form ("sphere_colors", "sphere_properties"; docs/scene-format.md,
// "Per-sphere colours and properties"), their checks, and their share of the
// content hash, which reads their bits rather than their text so that a
// million colours hash in milliseconds.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

#include "json_reader.h"
#include "orb/scene/content_hash.h"
#include "orb/scene/sphere_attributes.h"
#include "scene_json_spheres.h"

namespace orb::detail {

// `colors` and `properties` are the sections at those keys, or null when absent.
SphereAttributes sphere_attributes_from_json(const JsonReader& r, const nlohmann::json* colors,
                                             const nlohmann::json* properties);

// ",\n  \"sphere_colors\": [...]" and ",\n  \"sphere_properties\": [...]",
// each only when it has content; nothing for a scene without attributes, so
// such scenes are written (and hashed) exactly as before the sections existed.
void write_sphere_attributes_json(const SphereAttributes& attributes, const JsonSink& sink);

// Throws InputError("source: sphere_colors[7]: ...") for arrays whose length
// is not the sphere count, colours outside [0, 1], values that are not
// finite, categories out of range, and names that are empty or repeated.
void validate_sphere_attributes(const SphereAttributes& attributes, std::size_t sphere_count,
                                const std::string& source);

// Adds the arrays' bits (with their lengths and names) to `hash`; nothing
// when they are empty.
void hash_sphere_attributes(const SphereAttributes& attributes, ContentHash& hash);

}  // namespace orb::detail
