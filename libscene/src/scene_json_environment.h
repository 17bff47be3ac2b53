// The "environment" section of the canonical scene JSON (docs/scene-format.md,
// "Environment"): reading it, writing it and checking it, texels included
// once a loader has attached them.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "json_reader.h"
#include "orb/scene/scene.h"

namespace orb::detail {

// `value` is the section at JSON path "environment".
Environment environment_from_json(const JsonReader& r, const nlohmann::json& value);

// Null for EnvironmentKind::None (the key is then omitted).
nlohmann::ordered_json environment_to_json(const Environment& environment);

// Throws InputError("source: environment...: ...") for values the renderer
// cannot use, and for attached texels that are not finite radiance >= 0
// (naming the texel).
void validate_environment(const Environment& environment, const std::string& source);

}  // namespace orb::detail
