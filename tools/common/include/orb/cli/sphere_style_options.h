// The options that colour and size spheres by their properties (--color-by,
// --colormap, --color-range, --radius-by, --radius-range, --radius-scale,
// --material), shared by orb-import and orb-render; the rules are libscene's
// (orb/import/sphere_styling.h, docs/orb-import.md "Colour and size by property").
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "orb/import/sphere_styling.h"

namespace orb::cli {

struct SphereStyleArguments {
    std::string color_by, colormap = "viridis", color_range, radius_by, radius_range, material;
    double radius_scale = 1.0;
    std::string legend;                     // --legend FILE.png (orb/cli/legend_output.h)
    std::string legend_layout = "vertical";  // --legend-layout vertical|horizontal
};

void add_sphere_style_options(CLI::App& app, SphereStyleArguments& arguments);

// Throws UsageError for a malformed range, an unknown colour map or preset,
// or --legend without --color-by or without a .png name.
SphereStyleOptions sphere_style_options(const SphereStyleArguments& arguments);

// Applies them and says what the colours mean ("cloud.ply: --color-by
// temperature: viridis over [300, 400]") on stderr; returns what it did (for --legend).
SphereStyleResult apply_sphere_style(Scene& scene, const SphereStyleOptions& options, const std::string& source);

}  // namespace orb::cli
