#include "orb/cli/sphere_style_options.h"

#include <cctype>
#include <cmath>
#include <sstream>

#include "orb/cli/messages.h"
#include "orb/cli/number_checks.h"
#include "orb/cli/tool_main.h"

namespace orb::cli {
namespace {

constexpr const char* kGroup = "Colour and size by property";

// "MIN,MAX": two finite numbers, MIN < MAX (MIN > MAX would reverse the map: say so instead).
std::pair<double, double> parse_range(const std::string& text, const char* option, bool positive) {
    const std::size_t comma = text.find(',');
    const std::optional<double> lo = comma == std::string::npos ? std::nullopt : parse_number(text.substr(0, comma));
    const std::optional<double> hi = comma == std::string::npos ? std::nullopt : parse_number(text.substr(comma + 1));
    if (!lo || !hi || !std::isfinite(*lo) || !std::isfinite(*hi) || !(*lo < *hi) || (positive && !(*lo > 0)))
        throw UsageError(std::string(option) + ": expected MIN,MAX, two finite numbers with MIN < MAX" +
                         (positive ? " and MIN > 0" : "") + ", got '" + text + "'");
    return {*lo, *hi};
}

}  // namespace

void add_sphere_style_options(CLI::App& app, SphereStyleArguments& a) {
    app.add_option("--color-by", a.color_by,
                   "Colour each particle (sphere that does not emit) by this per-sphere property: a numeric one "
                   "through --colormap, a categorical one (element, chain, ...) one colour per category")
        ->option_text("PROPERTY")
        ->group(kGroup);
    app.add_option("--colormap", a.colormap, "Colour map for --color-by: " + colormap_names() + " (default viridis)")
        ->option_text("NAME")
        ->group(kGroup);
    app.add_option("--color-range", a.color_range,
                   "Values mapped onto the colour map's ends (default: the particles' min and max; outside: clamped)")
        ->option_text("MIN,MAX")
        ->group(kGroup);
    app.add_option("--radius-by", a.radius_by,
                   "Size each particle by this numeric property: its min..max maps linearly onto --radius-range")
        ->option_text("PROPERTY")
        ->group(kGroup);
    app.add_option("--radius-range", a.radius_range, "Radii, in scene units, of --radius-by's smallest and largest value")
        ->option_text("MIN,MAX")
        ->group(kGroup);
    app.add_option("--radius-scale", a.radius_scale,
                   "Multiply every particle's radius by this factor (after --radius-by; default 1)")
        ->check(finite_number_where([](double v) { return v > 0; }, "a number > 0"))
        ->option_text("FACTOR")
        ->group(kGroup);
    app.add_option("--legend", a.legend,
                   "Write a legend of --color-by's colours to this PNG file: a colour bar with the property's name "
                   "and values, or a swatch per category with its label")
        ->option_text("FILE.png")
        ->group(kGroup);
    app.add_option("--legend-layout", a.legend_layout, "The legend's bar upright or lying down (default vertical)")
        ->check(CLI::IsMember({"vertical", "horizontal"}))
        ->option_text("vertical|horizontal")
        ->group(kGroup);
    app.add_option("--material", a.material,
                   "Every particle's material, keeping its colour: matte (diffuse), plastic (glossy coat) or metal")
        ->option_text("PRESET")
        ->group(kGroup);
}

SphereStyleOptions sphere_style_options(const SphereStyleArguments& a) {
    SphereStyleOptions options;
    options.color_by = a.color_by;
    const std::optional<Colormap> map = colormap_from_name(a.colormap);
    if (!map) throw UsageError("--colormap: expected one of " + colormap_names() + ", got '" + a.colormap + "'");
    options.colormap = *map;
    if (!a.color_range.empty()) {
        if (a.color_by.empty()) throw UsageError("--color-range needs --color-by PROPERTY");
        options.color_range = parse_range(a.color_range, "--color-range", false);
    }
    options.radius_by = a.radius_by;
    if (!a.radius_range.empty()) {
        if (a.radius_by.empty()) throw UsageError("--radius-range needs --radius-by PROPERTY");
        options.radius_range = parse_range(a.radius_range, "--radius-range", true);
    } else if (!a.radius_by.empty()) {
        throw UsageError("--radius-by " + a.radius_by + " needs --radius-range MIN,MAX (the radii of its smallest "
                         "and largest value)");
    }
    options.radius_scale = a.radius_scale;
    if (!a.material.empty()) {
        options.material = material_preset_from_name(a.material);
        if (!options.material)
            throw UsageError("--material: expected matte, plastic or metal, got '" + a.material + "'");
    }
    if (!a.legend.empty()) {
        if (a.color_by.empty())
            throw UsageError("--legend " + a.legend + " needs --color-by PROPERTY: the legend says what its colours mean");
        const std::size_t dot = a.legend.rfind('.');
        std::string extension = dot == std::string::npos ? "" : a.legend.substr(dot);
        for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (extension != ".png") throw UsageError("--legend: expected a PNG file name (FILE.png), got '" + a.legend + "'");
    } else if (a.legend_layout != "vertical") {
        throw UsageError("--legend-layout needs --legend FILE.png");
    }
    return options;
}

SphereStyleResult apply_sphere_style(Scene& scene, const SphereStyleOptions& options, const std::string& source) {
    const SphereStyleResult result = apply_sphere_styling(scene, options, source);
    if (result.color_range) {
        std::ostringstream text;
        text << source << ": --color-by " << options.color_by << ": " << colormap_name(options.colormap) << " from "
             << result.color_range->first << " to " << result.color_range->second;
        info(text.str());
    }
    return result;
}

}  // namespace orb::cli
