// The "spheres" array of the JSON form, written directly rather than through
// JSON values: the same bytes format_json would make, at a fraction of the
// cost, since a million spheres are the normal case for point clouds and
// orb-render hashes the JSON of every scene it renders.
#pragma once

#include <string>
#include <vector>

#include "orb/scene/scene.h"

namespace orb::detail {

// "[]", or "[\n    { ... },\n    { ... }\n  ]" at the top level's depth.
std::string format_spheres_json(const std::vector<Sphere>& spheres);

}  // namespace orb::detail
