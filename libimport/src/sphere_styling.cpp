#include "orb/import/sphere_styling.h"

#include "orb/import/elements.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "orb/scene/detail/json_text.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"
#include "srgb.h"

namespace orb {
namespace {

struct PresetRow {
    MaterialPreset preset;
    const char* name;
};
constexpr PresetRow kPresets[] = {
    {MaterialPreset::Matte, "matte"}, {MaterialPreset::Plastic, "plastic"}, {MaterialPreset::Metal, "metal"}};

bool emits(const Material& material) {
    return material.emission[0] > 0 || material.emission[1] > 0 || material.emission[2] > 0;
}

// The particles: the spheres whose material does not emit.
std::vector<bool> particles_of(const Scene& scene) {
    std::vector<bool> emissive_material(scene.materials.size());
    for (std::size_t m = 0; m < scene.materials.size(); ++m) emissive_material[m] = emits(scene.materials[m]);
    std::vector<bool> particles(scene.spheres.size());
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        particles[i] = !emissive_material.at(scene.spheres[i].material);
    return particles;
}

const SphereProperty& find_property(const Scene& scene, const std::string& name, const char* option,
                                    const std::string& source) {
    const std::vector<SphereProperty>& properties = scene.sphere_attributes.properties;
    for (const SphereProperty& property : properties)
        if (property.name == name) return property;
    std::string has;
    for (const SphereProperty& property : properties) has += (has.empty() ? "" : ", ") + property.name;
    throw InputError(source + ": " + option + " " + name + ": no such sphere property (" +
                     (has.empty() ? std::string("the scene has no per-sphere properties") : "the scene has: " + has) +
                     ")");
}

// The particles that have a value of `property`: a molecule's cell has none, and keeps its look.
std::vector<bool> valued_particles(const SphereProperty& property, std::vector<bool> particles) {
    for (std::size_t i = 0; i < particles.size(); ++i) particles[i] = particles[i] && has_value(property.values[i]);
    return particles;
}

std::pair<double, double> particle_range(const SphereProperty& property, const std::vector<bool>& particles) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < property.values.size(); ++i) {
        if (!particles[i]) continue;
        lo = std::min(lo, static_cast<double>(property.values[i]));
        hi = std::max(hi, static_cast<double>(property.values[i]));
    }
    return {lo, hi};
}

// Where `value` lies in [lo, hi], clamped; the middle for an empty range (all equal).
double fraction_in(double value, const std::pair<double, double>& range) {
    const double width = range.second - range.first;
    if (!(width != 0)) return 0.5;
    return std::clamp((value - range.first) / width, 0.0, 1.0);
}

void color_by(Scene& scene, const SphereStyleOptions& options, const std::vector<bool>& all_particles,
              const std::string& source, SphereStyleResult& result) {
    const SphereProperty& property = find_property(scene, options.color_by, "--color-by", source);
    const std::vector<bool> particles = valued_particles(property, all_particles);
    std::vector<float>& colors = scene.sphere_attributes.colors;
    if (colors.empty()) {  // the lights keep their material's colour
        colors.resize(3 * scene.spheres.size());
        for (std::size_t i = 0; i < scene.spheres.size(); ++i)
            for (int c = 0; c < 3; ++c)
                colors[3 * i + c] = static_cast<float>(scene.materials[scene.spheres[i].material].color[c]);
    }
    auto set = [&colors](std::size_t i, const std::array<float, 3>& display) {
        for (int c = 0; c < 3; ++c) colors[3 * i + c] = static_cast<float>(detail::srgb_to_linear(display[c]));
    };
    if (property.categorical()) {
        // One colour per category, computed once.
        std::vector<std::array<float, 3>> palette;
        for (std::size_t k = 0; k < property.labels.size(); ++k)
            palette.push_back(category_display_color(property.name, k, property.labels[k]));
        std::vector<bool> present(palette.size());
        for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
            if (!particles[i]) continue;
            const std::size_t category = static_cast<std::size_t>(property.values[i]);
            set(i, palette.at(category));
            present[category] = true;
        }
        ColorLegend& legend = result.legend.emplace();
        legend.property = property.name;
        legend.categorical = true;
        for (std::size_t k = 0; k < palette.size(); ++k)
            if (present[k]) legend.categories.push_back({property.labels[k], palette[k]});
        return;
    }
    const std::pair<double, double> range = options.color_range.value_or(particle_range(property, particles));
    result.color_range = range;
    result.legend = ColorLegend{property.name, false, options.colormap, range, {}};
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        if (particles[i]) set(i, colormap_display_color(options.colormap, fraction_in(property.values[i], range)));
}

void radius_by(Scene& scene, const SphereStyleOptions& options, const std::vector<bool>& all_particles,
               const std::string& source, SphereStyleResult& result) {
    const SphereProperty& property = find_property(scene, options.radius_by, "--radius-by", source);
    const std::vector<bool> particles = valued_particles(property, all_particles);
    if (property.categorical())
        throw InputError(source + ": --radius-by " + property.name +
                         ": a categorical property (labels such as \"" + property.labels.front() +
                         "\") has no size order; use a numeric property");
    const std::pair<double, double> values = particle_range(property, particles);
    result.radius_values = values;
    const auto [r0, r1] = *options.radius_range;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        if (particles[i]) scene.spheres[i].radius = r0 + (r1 - r0) * fraction_in(property.values[i], values);
}

void apply_preset(Scene& scene, MaterialPreset preset, const std::vector<bool>& particles) {
    std::vector<bool> used(scene.materials.size());
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        if (particles[i]) used[scene.spheres[i].material] = true;
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        if (!used[m]) continue;
        Material& material = scene.materials[m];
        material.type = preset == MaterialPreset::Matte ? MaterialType::Diffuse : MaterialType::Pbr;
        material.roughness = preset == MaterialPreset::Matte ? 0.0 : preset == MaterialPreset::Plastic ? 0.4 : 0.3;
        material.metallic = preset == MaterialPreset::Metal ? 1.0 : 0.0;
        material.ior = 1.5;
    }
}

}  // namespace

const char* material_preset_name(MaterialPreset preset) {
    for (const PresetRow& row : kPresets)
        if (row.preset == preset) return row.name;
    return "matte";
}

std::optional<MaterialPreset> material_preset_from_name(std::string_view name) {
    for (const PresetRow& row : kPresets)
        if (name == row.name) return row.preset;
    return std::nullopt;
}

std::array<float, 3> category_display_color(std::string_view property, std::size_t index, std::string_view label) {
    // Elements keep the colours chemists know (Jmol's CPK colours, the
    // element table's); a symbol the table lacks falls back to the palette.
    if (property == "element")
        if (const Element* element = find_element(label))
            return {element->jmol_srgb[0] / 255.0f, element->jmol_srgb[1] / 255.0f, element->jmol_srgb[2] / 255.0f};
    return qualitative_display_color(index);
}

SphereStyleResult apply_sphere_styling(Scene& scene, const SphereStyleOptions& options, const std::string& source) {
    SphereStyleResult result;
    if (options.empty()) return result;
    const std::vector<bool> particles = particles_of(scene);
    if (std::find(particles.begin(), particles.end(), true) == particles.end())
        throw InputError(source + ": no sphere to style (--color-by, --radius-by, --radius-scale and --material apply "
                                  "to spheres that do not emit, and every sphere emits)");
    if (!options.radius_by.empty() && !options.radius_range)
        throw InputError(source + ": --radius-by " + options.radius_by + " needs --radius-range MIN,MAX");
    if (!options.color_by.empty()) color_by(scene, options, particles, source, result);
    if (!options.radius_by.empty()) radius_by(scene, options, particles, source, result);
    if (options.radius_scale != 1.0)
        for (std::size_t i = 0; i < scene.spheres.size(); ++i)
            if (particles[i]) scene.spheres[i].radius *= options.radius_scale;
    if (options.material) apply_preset(scene, *options.material, particles);
    validate_scene(scene, source);  // a scaled radius past the float limits is named like any other
    return result;
}

}  // namespace orb
