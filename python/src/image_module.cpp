// The extension module orb._image: what orb.Image shows through OpenImageIO
// and OpenColorIO (to_srgb, to_srgb8 and the PNG made of it), as orb-tonemap
// shows an image by default. It is apart from orb._orb so that importing orb,
// rendering and saving EXR need neither library (their closure is over
// 300 MiB, more than a bare GPU node is given); orb/__init__.py imports it on
// the first call that needs it (docs/design/python-bindings.md).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "orb/image/color_config.h"
#include "orb/image/passes.h"
#include "orb/image/quantize.h"
#include "orb/image/tonemap.h"

namespace py = pybind11;

namespace orb::python {
namespace {

using Pixels = py::array_t<float, py::array::c_style | py::array::forcecast>;

// A layer (its (H, W, C) pixels, as orb.Image's layer arrays hold them, and
// its channel names) as orb-tonemap shows it by default: opaque (what the
// camera sees, the beauty's alpha left out) through the default display view
// of Orb's OpenColorIO config at `config_path` ($OCIO wins, as in the tools).
image::Image display_image(const Pixels& pixels, const std::vector<std::string>& channels, const std::string& name,
                           const std::string& config_path) {
    if (pixels.ndim() != 3 || pixels.shape(2) != static_cast<py::ssize_t>(channels.size()))
        throw py::value_error("expected (H, W, C) pixels with a name for each of the C channels");
    image::Image whole(static_cast<int>(pixels.shape(1)), static_cast<int>(pixels.shape(0)), channels);
    std::copy(pixels.data(), pixels.data() + pixels.size(), whole.pixels.begin());
    image::Pass pass = image::extract_pass(whole, name, "image");
    if (pass.has_alpha) {
        pass.image = image::select_channels(pass.image, {0, 1, 2}, {"R", "G", "B"});
        pass.has_alpha = false;
    }
    const image::ColorConfig config = image::ColorConfig::load("", config_path);
    const image::DisplayView view = image::resolve_display_view(config, {});
    return image::tonemap_pass(pass, config, view);
}

template <typename T>
py::array_t<T> image_array(const image::Image& shown, const std::vector<T>& values) {
    py::array_t<T> out({static_cast<py::ssize_t>(shown.height), static_cast<py::ssize_t>(shown.width),
                        static_cast<py::ssize_t>(shown.channels())});
    std::copy(values.begin(), values.end(), out.mutable_data());
    return out;
}

py::array_t<float> display_floats(const Pixels& pixels, const std::vector<std::string>& channels,
                                  const std::string& name, const std::string& config_path) {
    const image::Image shown = display_image(pixels, channels, name, config_path);
    return image_array(shown, shown.pixels);
}

// The 8-bit values orb-tonemap writes to a PNG (its dither, orb/image/quantize.h).
py::array_t<std::uint8_t> display_bytes(const Pixels& pixels, const std::vector<std::string>& channels,
                                        const std::string& name, const std::string& config_path) {
    const image::Image shown = display_image(pixels, channels, name, config_path);
    return image_array(shown, image::quantize_8bit_dithered(shown));
}

}  // namespace
}  // namespace orb::python

PYBIND11_MODULE(_image, module) {
    module.doc() = "orb.Image's display through OpenImageIO and OpenColorIO (docs/python.md)";
    // A config Orb cannot use (a bad $OCIO) is orb.Error, as the core's
    // library errors are (errors.h): the class is the core module's, held for
    // the process's life (never released at exit, after the interpreter).
    static PyObject* const error = py::object(py::module_::import("orb._orb").attr("Error")).release().ptr();
    py::register_local_exception_translator([](std::exception_ptr thrown) {
        try {
            if (thrown) std::rethrow_exception(thrown);
        } catch (const py::builtin_exception&) {
            throw;
        } catch (const py::error_already_set&) {
            throw;
        } catch (const std::bad_alloc&) {
            throw;
        } catch (const std::exception& e) {
            PyErr_SetString(error, e.what());
        }
    });
    module.def("display", &orb::python::display_floats);
    module.def("display8", &orb::python::display_bytes);
}
