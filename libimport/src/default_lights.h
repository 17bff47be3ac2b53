// Private: the two lights an importer adds to a scene that brings none (PLY
// point clouds, molecules and particles), documented in docs/orb-import.md.
#pragma once

#include "orb/scene/scene.h"

namespace orb::detail {

// Two emissive spheres of radius R (half the framed box's diagonal), 4R from its centre
// (outside the camera's view): a key light from the upper left giving an
// irradiance of 0.8·π at the centre and a fill light from the right giving
// 0.3·π. A sphere of radiance L seen at sin θ = 1/4 gives E = π·L/16.
// They are the last two spheres and materials.
void add_default_lights(Scene& scene, const Vec3& center, double radius);

}  // namespace orb::detail
