// The extension module orb._orb; the package orb (python/orb/__init__.py)
// wraps it with Python's keyword arguments and numpy's conveniences.
#include <pybind11/pybind11.h>

#include "devices.h"
#include "errors.h"
#include "orb/cli/messages.h"
#include "progressive_render.h"
#include "render_bindings.h"
#include "scene_bindings.h"

PYBIND11_MODULE(_orb, module) {
    module.doc() = "Orb's path tracer for sphere scenes (docs/python.md)";
    // The libraries' notes on stderr read "orb: warning: ..." as a tool's do.
    orb::cli::set_tool_name("orb");
    orb::python::register_errors(module);
    orb::python::bind_camera(module);
    orb::python::bind_scene(module);
    orb::python::bind_rendering(module);
    orb::python::bind_progressive_rendering(module);
    orb::python::bind_devices(module);
}
