// Colour and size spheres by their named properties (Scene::sphere_attributes):
// what orb-import's and orb-render's --color-by, --radius-by, --radius-scale
// and --material do (docs/orb-import.md, "Colour and size by property"), in
// the scene model so that any reader (a trajectory's every frame) applies
// the same rules.
//
// Styling touches the particles only: the spheres whose material does not
// emit. Lights (an importer's default lights, emissive spheres) keep their
// size, material and colour, and their values count for no range.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "orb/import/colormaps.h"
#include "orb/scene/scene.h"

namespace orb {

// A look for every particle's material, keeping its colour.
enum class MaterialPreset {
    Matte,    // diffuse
    Plastic,  // pbr, roughness 0.4, metallic 0: a dielectric base with a glossy coat
    Metal,    // pbr, roughness 0.3, metallic 1: the colour is the metal's reflectance
};
const char* material_preset_name(MaterialPreset preset);
std::optional<MaterialPreset> material_preset_from_name(std::string_view name);

struct SphereStyleOptions {
    // --color-by: a property's name. A numeric property goes through
    // `colormap` over `color_range` (default: the particles' own min and
    // max); a categorical one through category_display_color.
    std::string color_by;
    Colormap colormap = Colormap::Viridis;
    std::optional<std::pair<double, double>> color_range;  // values outside are clamped to its ends
    // --radius-by: a numeric property mapped linearly from its range over the
    // particles onto `radius_range` (required with it): min -> first, max -> second.
    std::string radius_by;
    std::optional<std::pair<double, double>> radius_range;
    // --radius-scale: every particle's radius times this (after radius_by); 1: unchanged.
    double radius_scale = 1.0;
    std::optional<MaterialPreset> material;

    bool empty() const {
        return color_by.empty() && radius_by.empty() && radius_scale == 1.0 && !material;
    }
};

// What --color-by's colours mean: what a legend image shows
// (orb/image/legend.h draws it). Colours are display (sRGB-encoded) values,
// the ones the particles' linear colours were decoded from.
struct ColorLegend {
    struct Category {
        std::string label;
        std::array<float, 3> display_color{};
    };
    std::string property;  // --color-by's property
    bool categorical = false;
    // A numeric property: `colormap` over `range` (first -> the map's start).
    Colormap colormap = Colormap::Viridis;
    std::pair<double, double> range{0.0, 0.0};
    // A categorical property: the categories the particles have, in the
    // property's label order, each with its colour.
    std::vector<Category> categories;
};

// What styling did, for the tools to say (and the legend to draw).
struct SphereStyleResult {
    // --color-by of a numeric property: the range mapped onto the colour map's ends.
    std::optional<std::pair<double, double>> color_range;
    std::optional<std::pair<double, double>> radius_values;  // --radius-by: the property's range over the particles
    std::optional<ColorLegend> legend;  // --color-by: what the colours mean
};

// The display (sRGB-encoded) colour of category `index`, labelled `label`,
// of the categorical property `property`. Every categorical colouring goes
// through this one function, so that a property with a colour convention of
// its own gets it here: "element" takes the element table's Jmol (CPK)
// colours (orb/import/elements.h); every other property, and a symbol the
// table lacks, Tableau 10 by index.
std::array<float, 3> category_display_color(std::string_view property, std::size_t index, std::string_view label);

// Applies `options` to `scene`; throws InputError naming `source` for a
// property the scene does not have (listing the ones it has), --radius-by of
// a categorical property, or a scene without particles to style. Leaves the
// scene valid (validate_scene) when it was.
SphereStyleResult apply_sphere_styling(Scene& scene, const SphereStyleOptions& options, const std::string& source);

}  // namespace orb
