// orb.Scene: the canonical scene (orb/scene/scene.h) made from arrays or a
// file, its camera, environment and lights, saved as JSON or .orb.
#include "scene_bindings.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <sstream>

#include "errors.h"
#include "keyword_options.h"
#include "orb/cli/environment_options.h"
#include "orb/cli/number_checks.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"
#include "scene_from_arrays.h"
#include "scene_loading.h"
#include "scene_saving.h"

namespace py = pybind11;

namespace orb::python {
namespace {

// The environment as Python sees it: None, an (R, G, B) radiance or a map's
// path with its intensity and rotation.
py::object environment_value(const Environment& environment) {
    switch (environment.kind) {
    case EnvironmentKind::None: return py::none();
    case EnvironmentKind::Color: return py::cast(environment.color);
    case EnvironmentKind::Map:
        return py::dict(py::arg("map") = environment.map, py::arg("intensity") = environment.intensity,
                        py::arg("rotation") = environment.rotation_deg);
    }
    return py::none();
}

// An --environment value that is not a radiance (numbers) names a map: a
// missing one is FileNotFoundError, as for orb.load's file.
bool names_a_missing_file(const std::string& value) {
    bool numbers = true;
    std::stringstream pieces(value);
    for (std::string piece; std::getline(pieces, piece, ',');) numbers = numbers && cli::parse_number(piece);
    std::error_code ignored;
    return !numbers && !std::filesystem::exists(value, ignored);
}

// --environment VALUE with its intensity and rotation, checked as the tools check them.
void set_environment(Scene& scene, const KeywordOptions& options) {
    CLI::App app{"orb.Scene.set_environment"};
    app.set_help_flag();
    cli::EnvironmentChoice choice;
    cli::add_environment_options(app, choice);
    parse_keyword_options(app, options, "set_environment");
    if (choice.value.empty()) {
        scene.environment = {};
        return;
    }
    try {
        scene.environment = *cli::chosen_environment(choice, ".");
    } catch (const InputError& e) {
        if (names_a_missing_file(choice.value)) throw_file_not_found(e.what());
        throw;
    }
}

// An emissive sphere of its own material, with empty entries in the
// per-sphere arrays (as the importers' default lights have).
void add_light(Scene& scene, const Vec3& center, double radius, const Vec3& emission) {
    Scene lit = scene;
    Material light;
    light.name = "light" + std::to_string(scene.materials.size());
    light.emission = emission;
    lit.materials.push_back(light);
    lit.spheres.push_back({light.name, center, radius, static_cast<std::uint32_t>(lit.materials.size() - 1)});
    SphereAttributes& attributes = lit.sphere_attributes;
    if (!attributes.colors.empty()) attributes.colors.insert(attributes.colors.end(), {0.0f, 0.0f, 0.0f});
    for (SphereProperty& property : attributes.properties) property.values.push_back(kNoValue);
    try {
        validate_scene(lit, "add_light");
    } catch (const InputError& e) {
        throw_value_error(e.what());
    }
    scene = std::move(lit);
}

py::list material_list(const Scene& scene) {
    py::list materials;
    for (const Material& m : scene.materials)
        materials.append(py::dict(py::arg("name") = m.name, py::arg("type") = material_type_name(m.type),
                                  py::arg("color") = m.color, py::arg("emission") = m.emission,
                                  py::arg("ior") = m.ior, py::arg("roughness") = m.roughness,
                                  py::arg("metallic") = m.metallic));
    return materials;
}

py::array_t<double> centers_of(const Scene& scene) {
    py::array_t<double> centers({static_cast<py::ssize_t>(scene.spheres.size()), py::ssize_t{3}});
    double* out = centers.mutable_data();
    for (const Sphere& sphere : scene.spheres)
        for (double c : sphere.center) *out++ = c;
    return centers;
}

py::array_t<double> radii_of(const Scene& scene) {
    py::array_t<double> radii(static_cast<py::ssize_t>(scene.spheres.size()));
    double* out = radii.mutable_data();
    for (const Sphere& sphere : scene.spheres) *out++ = sphere.radius;
    return radii;
}

// A render setting, checked by the scene format's rules.
void set_render_setting(Scene& scene, int RenderSettings::*setting, int value) {
    Scene changed;
    changed.render = scene.render;
    changed.render.*setting = value;
    changed.materials.emplace_back();
    changed.spheres.emplace_back();
    try {
        validate_scene(changed, "Scene");
    } catch (const InputError& e) {
        throw_value_error(e.what());
    }
    scene.render.*setting = value;
}

}  // namespace

void bind_scene(py::module_& module) {
    py::class_<Scene> scene(module, "Scene", "A scene of spheres (docs/python.md).");
    scene.def_static("_from_arrays", &scene_from_arrays)
        .def_static("_load",
                    [](const std::string& path, const KeywordOptions& options) {
                        LoadedScene loaded = load_scene(path, options);
                        return std::make_pair(std::move(loaded.scene), std::move(loaded.warnings));
                    })
        .def_static("_load_text",
                    [](const std::string& source, const std::string& text, const KeywordOptions& options) {
                        LoadedScene loaded = load_scene(source, options, &text);
                        return std::make_pair(std::move(loaded.scene), std::move(loaded.warnings));
                    })
        .def("_set_camera", &set_camera_options)
        .def("_set_environment", &set_environment)
        .def("__len__", [](const Scene& s) { return s.spheres.size(); })
        .def_property_readonly(
            "camera", [](Scene& s) -> Camera& { return s.camera; }, py::return_value_policy::reference_internal)
        .def_property_readonly("environment", [](const Scene& s) { return environment_value(s.environment); })
        .def("add_light", &add_light, py::arg("center"), py::arg("radius"), py::arg("emission"),
             "Adds an emissive sphere: `emission` is its radiance (R, G, B).")
        .def_property_readonly("materials", &material_list)
        .def_property_readonly("centers", &centers_of, "The spheres' centres, (N, 3) float64 (a copy).")
        .def_property_readonly("radii", &radii_of, "The spheres' radii, (N,) float64 (a copy).")
        .def_property(
            "width", [](const Scene& s) { return s.render.width; },
            [](Scene& s, int v) { set_render_setting(s, &RenderSettings::width, v); })
        .def_property(
            "height", [](const Scene& s) { return s.render.height; },
            [](Scene& s, int v) { set_render_setting(s, &RenderSettings::height, v); })
        .def_property(
            "spp", [](const Scene& s) { return s.render.spp; },
            [](Scene& s, int v) { set_render_setting(s, &RenderSettings::spp, v); })
        .def_property(
            "max_depth", [](const Scene& s) { return s.render.max_depth; },
            [](Scene& s, int v) { set_render_setting(s, &RenderSettings::max_depth, v); })
        .def("_save", &save_scene)
        .def("to_json", &write_scene_json, "The canonical Orb JSON text.")
        .def("__eq__", [](const Scene& a, const Scene& b) { return a == b; }, py::is_operator())
        .def("__repr__", [](const Scene& s) {
            return "<orb.Scene: " + std::to_string(s.spheres.size()) + " spheres, " +
                   std::to_string(s.materials.size()) + " materials>";
        });
}

}  // namespace orb::python
