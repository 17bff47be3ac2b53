#include "render_bindings.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <atomic>
#include <memory>

#include "errors.h"
#include "orb/job/render_job.h"
#include "orb/scene/scene.h"
#include "still_render.h"

namespace py = pybind11;

namespace orb::python {
namespace {

const job::Layer& layer_named(const RenderedLayers& rendered, const std::string& name) {
    for (const job::Layer& layer : rendered.layers)
        if (layer.name == name) return layer;
    std::string names;
    for (const job::Layer& layer : rendered.layers) names += (names.empty() ? "" : ", ") + layer.name;
    throw py::key_error("no layer '" + name + "' in the image (it has " + names + ")");
}

// (H, W, C) float32 over the layer's pixels, no copy.
py::array_t<float> layer_array(const py::object& owner, const job::Layer& layer) {
    const auto channels = static_cast<py::ssize_t>(layer.channels.size());
    const py::ssize_t f = sizeof(float);
    return py::array_t<float>({static_cast<py::ssize_t>(layer.height), static_cast<py::ssize_t>(layer.width), channels},
                              {layer.width * channels * f, channels * f, f}, layer.pixels.data(), owner);
}

py::dict progress_dict(const job::Progress& p) {
    return py::dict(py::arg("pass") = p.pass, py::arg("spp") = p.spp, py::arg("target_spp") = p.target_spp,
                    py::arg("elapsed_seconds") = p.elapsed_seconds,
                    py::arg("samples_per_second") = p.samples_per_second);
}

std::shared_ptr<RenderedLayers> render(const Scene& posed, int width, int height, std::uint64_t spp,
                                       std::uint64_t seed, const std::string& device,
                                       const std::vector<std::string>& passes, bool denoise,
                                       std::optional<double> target_error, std::optional<double> noise_threshold,
                                       std::optional<double> time_limit, const py::object& progress) {
    job::StillSettings settings = still_settings(width, height, spp, seed, device, passes, denoise, target_error,
                                                 noise_threshold, time_limit);
    std::vector<std::string> warnings;
    settings.on_message = [&warnings](job::MessageKind kind, const std::string& message) {
        if (kind != job::MessageKind::Info) warnings.push_back(message);
    };
    Scene with_map;
    const Scene* scene = &scene_to_render(posed, with_map);

    // Ctrl-C: the render stops after the pass in flight, then KeyboardInterrupt.
    bool interrupted = false;
    py::object callback_error;
    const job::ProgressCallback on_pass = [&](const job::Progress& now, const job::PreviewAccess&) {
        py::gil_scoped_acquire held;
        if (PyErr_CheckSignals() != 0) {
            PyErr_Clear();
            interrupted = true;
            return false;
        }
        if (progress.is_none()) return true;
        try {
            const py::object answer = progress(progress_dict(now));
            return answer.is_none() || PyObject_IsTrue(answer.ptr()) == 1;  // False stops the render
        } catch (py::error_already_set& e) {
            callback_error = py::reinterpret_borrow<py::object>(e.value());
            return false;
        }
    };
    job::RenderedImage image;
    {
        py::gil_scoped_release released;
        image = job::render_still(*scene, settings, on_pass);
    }
    std::shared_ptr<RenderedLayers> rendered = with_layers(std::move(image));
    py::module_ warnings_module = py::module_::import("warnings");
    for (const std::string& message : warnings) warnings_module.attr("warn")(message);
    if (interrupted) {
        PyErr_SetNone(PyExc_KeyboardInterrupt);
        throw py::error_already_set();
    }
    if (callback_error) {
        PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(callback_error.ptr())), callback_error.ptr());
        throw py::error_already_set();
    }
    return rendered;
}

}  // namespace

void bind_rendering(py::module_& module) {
    py::class_<RenderedLayers, std::shared_ptr<RenderedLayers>>(module, "Image",
                                                                "A rendered image (docs/python.md, \"Rendering\").")
        .def_property_readonly("layer_names",
                               [](const RenderedLayers& r) {
                                   std::vector<std::string> names;
                                   for (const job::Layer& layer : r.layers) names.push_back(layer.name);
                                   return names;
                               })
        .def(
            "__getitem__",
            [](const py::object& self, const std::string& name) {
                return layer_array(self, layer_named(self.cast<const RenderedLayers&>(), name));
            },
            "A layer as a (H, W, C) float32 array that shares the image's memory.")
        .def("channels", [](const RenderedLayers& r, const std::string& name) { return layer_named(r, name).channels; })
        .def_property_readonly("stopped", [](const RenderedLayers& r) { return r.image.stopped; })
        .def_property_readonly("final", [](const RenderedLayers& r) { return !r.image.snapshot; })
        .def_property_readonly("spp", [](const RenderedLayers& r) { return r.image.stats.spp; })
        .def_property_readonly("width", [](const RenderedLayers& r) { return r.image.film.width; })
        .def_property_readonly("height", [](const RenderedLayers& r) { return r.image.film.height; })
        .def_property_readonly("seed", [](const RenderedLayers& r) { return r.image.metadata.seed; })
        .def_property_readonly("device", [](const RenderedLayers& r) { return r.image.metadata.device; })
        .def_property_readonly("render_seconds", [](const RenderedLayers& r) { return r.image.metadata.render_seconds; })
        .def("encode_exr",
             [](const RenderedLayers& r) {
                 std::string bytes;
                 {
                     py::gil_scoped_release released;
                     bytes = r.image.encode_exr();
                 }
                 return py::bytes(bytes);
             })
        .def("_save_exr",
             [](const RenderedLayers& r, const std::string& path) {
                 py::gil_scoped_release released;
                 r.image.save_exr(path);
             });
    module.def("_render", &render);
}

}  // namespace orb::python
