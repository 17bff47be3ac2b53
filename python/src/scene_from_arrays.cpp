#include "scene_from_arrays.h"

#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <string_view>

#include "errors.h"
#include "numpy_arrays.h"
#include "orb/import/point_cloud.h"
#include "orb/import/sphere_styling.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"

namespace py = pybind11;

namespace orb::python {
namespace {

constexpr const char* kSource = "Scene.from_arrays";

std::vector<Sphere> spheres_of(const py::handle& centers_value, const py::handle& radii_value) {
    const DoubleRows centers = double_array(centers_value, "centers", -1, 3);
    const long count = static_cast<long>(centers.shape(0));
    if (count == 0) throw_value_error("centers: expected at least one sphere, got shape (0, 3)");
    const bool one_radius = py::isinstance<py::float_>(radii_value) || py::isinstance<py::int_>(radii_value);
    const DoubleRows radii = one_radius ? DoubleRows() : double_array(radii_value, "radii", count, 0);
    const double radius = one_radius ? radii_value.cast<double>() : 0.0;
    std::vector<Sphere> spheres(static_cast<std::size_t>(count));
    const double* c = centers.data();
    const double* r = one_radius ? nullptr : radii.data();
    for (long i = 0; i < count; ++i) {
        Sphere& sphere = spheres[static_cast<std::size_t>(i)];
        sphere.center = {c[3 * i], c[3 * i + 1], c[3 * i + 2]};
        sphere.radius = r ? r[i] : radius;
    }
    return spheres;
}

std::vector<float> linear_colors(const py::handle& colors_value, long count) {
    if (colors_value.is_none()) return {};
    const DoubleRows colors = double_array(colors_value, "colors", count, 3);
    const double* display = colors.data();
    std::vector<float> linear(static_cast<std::size_t>(3 * count));
    for (std::size_t i = 0; i < linear.size(); ++i) {
        // Out of [0, 1] (or NaN) stays so, for validate_scene to name.
        const double value = display[i];
        linear[i] = value >= 0.0 && value <= 1.0 ? static_cast<float>(linear_from_display(value))
                                                  : static_cast<float>(value);
    }
    return linear;
}

std::vector<SphereProperty> properties_of(const py::list& properties, long count) {
    std::vector<SphereProperty> result;
    for (const py::handle item : properties) {
        const auto [name, values_value, labels] =
            item.cast<std::tuple<std::string, py::object, std::vector<std::string>>>();
        const DoubleRows values = double_array(values_value, "properties['" + name + "']", count, 0);
        SphereProperty property;
        property.name = name;
        property.labels = labels;
        property.values.assign(values.data(), values.data() + count);  // float, as the scene keeps them
        result.push_back(std::move(property));
    }
    return result;
}

// A material key's value as `T`, else ValueError naming the key and what it takes.
template <typename T>
T material_value(const py::handle& value, const std::string& key, const char* expected) {
    try {
        return value.cast<T>();
    } catch (const py::cast_error&) {
        throw_value_error("material['" + key + "']: expected " + expected + ", got " +
                          std::string(py::repr(value)));
    }
}

// The shared material as a dict of the scene format's keys (docs/scene-format.md).
Material material_of(const py::dict& keys, Material material) {
    for (const auto& [key_value, value] : keys) {
        if (!py::isinstance<py::str>(key_value))
            throw_value_error("material: expected str keys, got " + std::string(py::repr(key_value)));
        const std::string key = key_value.cast<std::string>();
        if (key == "type") {
            const std::string type = material_value<std::string>(value, key, "a material type's name");
            bool known = false;
            for (MaterialType candidate : kMaterialTypes)
                if (type == material_type_name(candidate)) material.type = candidate, known = true;
            if (!known) throw_value_error("material['type']: unknown material type '" + type + "'");
        } else if (key == "color") {
            material.color = material_value<Vec3>(value, key, "(R, G, B) numbers");
        } else if (key == "emission") {
            material.emission = material_value<Vec3>(value, key, "(R, G, B) numbers");
        } else if (key == "ior") {
            material.ior = material_value<double>(value, key, "a number");
        } else if (key == "roughness") {
            material.roughness = material_value<double>(value, key, "a number");
        } else if (key == "metallic") {
            material.metallic = material_value<double>(value, key, "a number");
        } else {
            throw_value_error("material: unknown key '" + key +
                              "' (expected type, color, emission, ior, roughness, metallic)");
        }
    }
    return material;
}

}  // namespace

Scene scene_from_arrays(const py::handle& centers, const py::handle& radii, const py::handle& colors,
                        const py::handle& material, const py::list& properties) {
    PointCloud cloud;
    cloud.spheres = spheres_of(centers, radii);
    const long count = static_cast<long>(cloud.spheres.size());
    cloud.colors = linear_colors(colors, count);
    cloud.properties = properties_of(properties, count);
    std::optional<MaterialPreset> preset;
    if (py::isinstance<py::str>(material)) {
        const std::string name = material.cast<std::string>();
        preset = material_preset_from_name(name);
        if (!preset) throw_value_error("material: unknown preset '" + name + "' (expected matte, plastic or metal)");
    } else if (!material.is_none() && !py::isinstance<py::dict>(material)) {
        throw_value_error("material: expected None, a preset's name or a dict of material keys");
    }
    // validate_scene names the first bad value with its place, as for a scene
    // file ("Scene.from_arrays: spheres[3].radius: must be > 0, got -2").
    try {
        Scene checked;  // before the camera frames them: NaN and negative radii first
        checked.materials.emplace_back();
        checked.spheres = std::move(cloud.spheres);
        checked.sphere_attributes.colors = std::move(cloud.colors);
        checked.sphere_attributes.properties = std::move(cloud.properties);
        validate_scene(checked, kSource);
        cloud.spheres = std::move(checked.spheres);
        cloud.colors = std::move(checked.sphere_attributes.colors);
        cloud.properties = std::move(checked.sphere_attributes.properties);
        double smallest = cloud.spheres.front().radius;
        for (const Sphere& sphere : cloud.spheres) smallest = std::min(smallest, sphere.radius);
        Scene scene = point_cloud_scene(std::move(cloud), smallest, kSource);
        if (preset) {
            SphereStyleOptions style;
            style.material = preset;
            apply_sphere_styling(scene, style, kSource);  // leaves a valid scene valid
        }
        if (py::isinstance<py::dict>(material)) {
            scene.materials[0] = material_of(material.cast<py::dict>(), scene.materials[0]);
            validate_scene(scene, kSource);  // the material's values
        }
        return scene;
    } catch (const InputError& e) {
        throw_value_error(e.what());
    }
}

}  // namespace orb::python
