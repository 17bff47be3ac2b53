// Scene.render and orb.Image: a still rendered through the render-job
// library (orb/job/render_job.h), the same code and contract as orb-render,
// its layers handed to numpy without a copy.
#pragma once

#include <pybind11/pybind11.h>

namespace orb::python {

void bind_rendering(pybind11::module_& module);

}  // namespace orb::python
