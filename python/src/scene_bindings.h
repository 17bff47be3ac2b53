// The Python classes orb.Scene and orb.Camera over the canonical scene model.
#pragma once

#include <pybind11/pybind11.h>

namespace orb::python {

void bind_camera(pybind11::module_& module);
void bind_scene(pybind11::module_& module);

}  // namespace orb::python
