// orb.devices().
#pragma once

#include <pybind11/pybind11.h>

namespace orb::python {

void bind_devices(pybind11::module_& module);

}  // namespace orb::python
