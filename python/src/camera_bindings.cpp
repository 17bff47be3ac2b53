// orb.Camera: the scene's camera, changed through the tools' camera options
// (orb/cli/camera_options.h) so that every value is checked as the command
// line checks it, with its message.
#include <pybind11/stl.h>

#include <charconv>

#include "keyword_options.h"
#include "orb/cli/camera_options.h"
#include "orb/cli/orbit_options.h"
#include "orb/scene/camera_orbit.h"
#include "scene_bindings.h"

namespace py = pybind11;

namespace orb::python {
namespace {

// A number as the command line would write it, exactly (shortest round trip).
std::string number_word(double value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::string(text, end);
}

std::string point_word(const Vec3& point) {
    return number_word(point[0]) + "," + number_word(point[1]) + "," + number_word(point[2]);
}

void set_camera(Camera& camera, const KeywordOptions& options) {
    CLI::App app{"orb.Camera"};
    app.set_help_flag();
    cli::CameraOptions parsed;
    cli::add_camera_options(app, parsed);
    parse_keyword_options(app, options, "Camera");
    Camera changed = camera;  // a change refused leaves the camera as it was
    cli::apply_camera_options(parsed, changed, "camera");
    camera = changed;
}

}  // namespace

void bind_camera(py::module_& module) {
    py::class_<Camera>(module, "Camera",
                       "The scene's camera (docs/python.md, \"Camera\"); each change is checked as orb-render's "
                       "camera options are.")
        .def_property(
            "position", [](const Camera& c) { return c.position; },
            [](Camera& c, const Vec3& p) { set_camera(c, {{"camera_position", point_word(p)}}); })
        .def_property(
            "target", [](const Camera& c) { return c.target; },
            [](Camera& c, const Vec3& p) { set_camera(c, {{"look_at", point_word(p)}}); })
        .def_property(
            "up", [](const Camera& c) { return c.up; },
            [](Camera& c, const Vec3& p) { set_camera(c, {{"up", point_word(p)}}); })
        .def_property(
            "vfov", [](const Camera& c) { return c.vfov_deg; },
            [](Camera& c, double v) { set_camera(c, {{"vfov", number_word(v)}}); })
        .def_property(
            "aperture", [](const Camera& c) { return c.aperture; },
            [](Camera& c, double v) { set_camera(c, {{"aperture", number_word(v)}}); })
        .def_property(
            "focus_distance", [](const Camera& c) { return c.focus_distance; },
            [](Camera& c, double v) { set_camera(c, {{"focus_distance", number_word(v)}}); })
        .def_property_readonly("orthographic_height", [](const Camera& c) { return c.orthographic_height; })
        .def(
            "look_at",
            [](Camera& c, const Vec3& target, std::optional<Vec3> position, std::optional<Vec3> up) {
                KeywordOptions options{{"look_at", point_word(target)}};
                if (position) options.push_back({"camera_position", point_word(*position)});
                if (up) options.push_back({"up", point_word(*up)});
                set_camera(c, options);
            },
            py::arg("target"), py::arg("position") = py::none(), py::arg("up") = py::none(),
            "Looks at `target`, from `position` and with `up` when given (--look-at, --camera-position, --up).")
        .def(
            "orbit",
            [](Camera& c, double degrees) {
                // Checked as orb-render's --orbit is: NaN would leave a camera that sees nothing.
                CLI::App app{"orb.Camera.orbit"};
                app.set_help_flag();
                cli::OrbitOptions orbit;
                cli::add_orbit_options(app, orbit);
                parse_keyword_options(app, {{"orbit", number_word(degrees)}}, "orbit");
                c = orbit_camera(c, *orbit.degrees);
            },
            py::arg("degrees"),
            "Turns the camera about its target along its up vector, right-handed (orb-render --orbit's turn).")
        .def(
            "orthographic", [](Camera& c, double height) { set_camera(c, {{"orthographic", number_word(height)}}); },
            py::arg("height"), "An orthographic view this many scene units high (--orthographic HEIGHT).")
        .def(
            "perspective",
            [](Camera& c, std::optional<double> vfov) {
                KeywordOptions options{{"perspective", std::nullopt}};
                if (vfov) options.push_back({"vfov", number_word(*vfov)});
                set_camera(c, options);
            },
            py::arg("vfov") = py::none(), "A perspective view again (--perspective, --vfov).")
        .def("__repr__", [](const Camera& c) {
            return "orb.Camera(position=(" + point_word(c.position) + "), target=(" + point_word(c.target) +
                   "), up=(" + point_word(c.up) + "), vfov=" + number_word(c.vfov_deg) +
                   (c.orthographic_height > 0 ? ", orthographic_height=" + number_word(c.orthographic_height) : "") +
                   ")";
        });
}

}  // namespace orb::python
