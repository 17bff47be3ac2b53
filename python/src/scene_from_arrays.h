// orb.Scene.from_arrays: a scene of spheres from numpy arrays, made as the
// PLY importer makes one from a point cloud's columns (orb/import/point_cloud.h):
// the same shared material, automatic camera and default lights.
#pragma once

#include <pybind11/pybind11.h>

#include "orb/scene/scene.h"

namespace orb::python {

// centers (N, 3); radii (N,) or one number; colors None or (N, 3) display
// (sRGB-encoded) values in [0, 1]; material None, a preset's name ("matte",
// "plastic", "metal") or a dict of the scene format's material keys;
// properties: a list of (name, values (N,) float, labels: a list of str,
// empty for a numeric property, else values are indices into it).
// Every value is checked as a scene file's are (validate_scene), the
// message raised as ValueError.
Scene scene_from_arrays(const pybind11::handle& centers, const pybind11::handle& radii,
                        const pybind11::handle& colors, const pybind11::handle& material,
                        const pybind11::list& properties);

}  // namespace orb::python
