// Turns the vertex columns of a PLY cloud into a scene that renders as is:
// spheres, shared materials, an automatic camera and two default lights.
#pragma once

#include <string>

#include "orb/import/ply.h"
#include "ply_read.h"

namespace orb::ply {

// Radius for points without one: half the spacing the points would have on
// a regular grid filling a cube with the cloud's bounding-box diagonal, the
// stray points left out as the automatic camera leaves them out
// (orb/scene/auto_framing.h; 1 when all points coincide). docs/orb-import.md documents the formula.
double default_point_radius(const std::vector<Vec3>& centers);

// Drops the properties a scene cannot hold (a value that is not a finite
// float) and returns a warning for each. (The header refuses repeated names.)
std::vector<std::string> keep_usable_properties(std::vector<SphereProperty>& properties, const std::string& source);

// The spheres' colours (linear, from the file's sRGB-encoded ones) and
// properties go to Scene::sphere_attributes, with one shared material.
// Throws InputError naming `source` when no camera can frame the cloud.
Scene cloud_scene(VertexColumns columns, const PlyImportOptions& options, const std::string& source);

}  // namespace orb::ply
