// orb.devices(): the OpenCL devices, as orb-render --list-devices lists them.
#include <pybind11/stl.h>

#include "devices.h"
#include "orb/job/render_job.h"

namespace py = pybind11;

namespace orb::python {

void bind_devices(py::module_& module) {
    module.def(
        "devices",
        [] {
            py::list listed;
            for (const job::DeviceListing& d : job::list_devices())
                listed.append(py::dict(py::arg("index") = d.index, py::arg("type") = d.type, py::arg("name") = d.name,
                                       py::arg("platform") = d.platform, py::arg("vendor") = d.vendor,
                                       py::arg("version") = d.version, py::arg("compute_units") = d.compute_units,
                                       py::arg("memory_bytes") = d.memory_bytes));
            return listed;
        },
        "Every OpenCL device, as orb-render --list-devices lists them: index, type, name, platform, ...");
}

}  // namespace orb::python
