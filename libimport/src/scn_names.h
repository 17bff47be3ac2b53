// Readable names for what a .scn file leaves unnamed: its materials and spheres.
#pragma once

#include <string>

#include "orb/scene/scene.h"

namespace orb::scn {

// "red diffuse", "white glass", "light", "green mirror light"...: the colour
// word comes from which channels dominate, so names stay stable across files.
std::string describe_material(const Material& material);

// "sphere 3": 1-based, in file order, so a name leads back to its line.
std::string sphere_name(size_t index);

}  // namespace orb::scn
