// Scene.render_progressive: the render on a thread of its own, its
// snapshots (orb/job/render_job.h, StillSettings::on_snapshot) handed to
// Python's generator one at a time, the newest first.
#pragma once

#include <pybind11/pybind11.h>

namespace orb::python {

void bind_progressive_rendering(pybind11::module_& module);

}  // namespace orb::python
