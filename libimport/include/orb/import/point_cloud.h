// The scene around spheres given as plain arrays, which renders as is: one
// shared grey material, the spheres' own colours and properties
// (Scene::sphere_attributes), the automatic camera looking from above the +z
// side and the two default lights. The PLY importer makes its scenes with it,
// and so does Python's orb.Scene.from_arrays, so that both frame and light a
// cloud by one rule (docs/orb-import.md, "PLY point clouds").
#pragma once

#include <string>
#include <vector>

#include "orb/scene/scene.h"

namespace orb {

struct PointCloud {
    std::vector<Sphere> spheres;  // centres and radii; each sphere's material is replaced by the shared one
    std::vector<float> colors;    // empty, or three linear Rec.709 values in [0, 1] per sphere
    std::vector<SphereProperty> properties;  // one value per sphere each
};

// Throws InputError naming `source` when no camera can frame the spheres
// (too far from the origin for their size). `point_radius` (> 0) is the
// smallest radius the lights are placed for (a lone point counts).
Scene point_cloud_scene(PointCloud cloud, double point_radius, const std::string& source);

// A display (sRGB-encoded) colour component in [0, 1] as the linear value
// the scene holds (IEC 61966-2-1's inverse): PLY colours, matplotlib's.
double linear_from_display(double encoded);

}  // namespace orb
