// JSON form of the "animation" section (owned by the glTF import work).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "orb/scene/animation.h"

namespace orb::detail {

// Returns an ordered JSON object, or null for an empty animation (key omitted).
nlohmann::ordered_json animation_to_json(const Animation& animation);

// `path` is the JSON path of the section ("animation"); throws InputError("source: path...: ...").
Animation animation_from_json(const nlohmann::json& value, const std::string& path, const std::string& source);

// Checks references (sphere/node indices) against the scene; throws InputError.
void validate_animation(const Animation& animation, std::size_t sphere_count, const std::string& source);

}  // namespace orb::detail
