// Colour maps against their sources' table values, and --color-by,
// --radius-by, --radius-scale and --material as libscene applies them.
#include <gtest/gtest.h>

#include <cmath>

#include "orb/import/colormaps.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"
#include "orb/import/sphere_styling.h"

namespace orb {
namespace {

void expect_color(const std::array<float, 3>& got, const std::array<float, 3>& expected, const char* what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-6) << what << ", component " << c;
}

// Entries 0, 130 and 255 of matplotlib 3.6.3's _cm_listed.py tables (kept rows
// of colormap_tables.cpp: every fifth entry), Moreland's CoolWarmFloat33 rows
// 0, 16 and 32, ColorBrewer Greys' ends and middle, Tableau 10's first and last.
TEST(Colormaps, EndsAndMiddlesAreTheSourcesValues) {
    expect_color(colormap_display_color(Colormap::Viridis, 0), {0.267004f, 0.004874f, 0.329415f}, "viridis 0");
    expect_color(colormap_display_color(Colormap::Viridis, 130.0 / 255), {0.125394f, 0.574318f, 0.549086f}, "viridis 130");
    expect_color(colormap_display_color(Colormap::Viridis, 1), {0.993248f, 0.906157f, 0.143936f}, "viridis 255");
    expect_color(colormap_display_color(Colormap::Magma, 0), {0.001462f, 0.000466f, 0.013866f}, "magma 0");
    expect_color(colormap_display_color(Colormap::Magma, 130.0 / 255), {0.729216f, 0.219437f, 0.471279f}, "magma 130");
    expect_color(colormap_display_color(Colormap::Magma, 1), {0.987053f, 0.991438f, 0.749504f}, "magma 255");
    expect_color(colormap_display_color(Colormap::Coolwarm, 0), {0.2298057f, 0.298717966f, 0.753683153f}, "coolwarm 0");
    expect_color(colormap_display_color(Colormap::Coolwarm, 0.5), {0.865395197f, 0.86541021f, 0.865395561f}, "coolwarm 0.5");
    expect_color(colormap_display_color(Colormap::Coolwarm, 1), {0.705673158f, 0.01555616f, 0.150232812f}, "coolwarm 1");
    expect_color(colormap_display_color(Colormap::Greys, 0), {1, 1, 1}, "greys 0");
    expect_color(colormap_display_color(Colormap::Greys, 0.5), {0.588235f, 0.588235f, 0.588235f}, "greys 0.5");
    expect_color(colormap_display_color(Colormap::Greys, 1), {0, 0, 0}, "greys 1");
    // Between rows: linear. Outside [0, 1] and NaN: clamped.
    const auto a = colormap_display_color(Colormap::Greys, 0.0), b = colormap_display_color(Colormap::Greys, 0.125);
    expect_color(colormap_display_color(Colormap::Greys, 0.0625),
                 {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2}, "greys between rows");
    expect_color(colormap_display_color(Colormap::Plasma, -3), colormap_display_color(Colormap::Plasma, 0), "below 0");
    expect_color(colormap_display_color(Colormap::Plasma, 7), colormap_display_color(Colormap::Plasma, 1), "above 1");
    expect_color(colormap_display_color(Colormap::Plasma, std::nan("")), colormap_display_color(Colormap::Plasma, 0), "NaN");
    expect_color(qualitative_display_color(0), {0x1f / 255.f, 0x77 / 255.f, 0xb4 / 255.f}, "tab10 0 (#1f77b4)");
    expect_color(qualitative_display_color(9), {0x17 / 255.f, 0xbe / 255.f, 0xcf / 255.f}, "tab10 9 (#17becf)");
    expect_color(qualitative_display_color(10), qualitative_display_color(0), "tab10 wraps");
    EXPECT_EQ(colormap_names(), "viridis, magma, plasma, inferno, cividis, coolwarm, greys");
    EXPECT_EQ(colormap_from_name("inferno"), Colormap::Inferno);
    EXPECT_EQ(colormap_from_name("Viridis"), std::nullopt);
}

float linear(float display) {
    return static_cast<float>(display <= 0.04045 ? display / 12.92 : std::pow((display + 0.055) / 1.055, 2.4));
}

// Four particles with a temperature and an element, and one light.
Scene particles() {
    Scene scene;
    scene.camera.position = {0, 0, 10};
    scene.materials = {{"p", MaterialType::Diffuse, {0.8, 0.8, 0.8}}, {"light", MaterialType::Diffuse, {0, 0, 0}, {5, 5, 5}}};
    for (int i = 0; i < 4; ++i) scene.spheres.push_back({"", {double(i), 0, 0}, 0.5, 0});
    scene.spheres.push_back({"", {0, 5, 0}, 2, 1});
    scene.sphere_attributes.properties = {{"temperature", {300, 350, 400, 325, 0}, {}},
                                          {"element", {0, 1, 0, 2, 0}, {"C", "O", "Fe"}}};
    return scene;
}

std::string styling_error(Scene scene, const SphereStyleOptions& options) {
    try {
        apply_sphere_styling(scene, options, "md.ply");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(SphereStyling, NumericColourByMapsTheParticlesRangeAndLeavesLightsAlone) {
    Scene scene = particles();
    SphereStyleOptions options;
    options.color_by = "temperature";
    const SphereStyleResult result = apply_sphere_styling(scene, options, "md.ply");
    ASSERT_TRUE(result.color_range);
    EXPECT_EQ(*result.color_range, (std::pair<double, double>{300, 400}));  // the light's 0 counts for nothing
    const std::vector<float>& colors = scene.sphere_attributes.colors;
    ASSERT_EQ(colors.size(), 15u);
    const auto lo = colormap_display_color(Colormap::Viridis, 0), hi = colormap_display_color(Colormap::Viridis, 1);
    for (int c = 0; c < 3; ++c) {
        EXPECT_FLOAT_EQ(colors[c], linear(lo[c]));      // 300: the map's start, decoded to linear
        EXPECT_FLOAT_EQ(colors[6 + c], linear(hi[c]));  // 400: its end
        EXPECT_EQ(colors[12 + c], 0.0f);                // the light: its material's colour
    }
    const auto quarter = colormap_display_color(Colormap::Viridis, 0.25);
    EXPECT_FLOAT_EQ(colors[9], linear(quarter[0]));  // 325
    validate_scene(scene, "md.ply");

    // A given range: values beyond it take its ends.
    Scene ranged = particles();
    options.color_range = {350, 360};
    options.colormap = Colormap::Greys;
    apply_sphere_styling(ranged, options, "md.ply");
    EXPECT_EQ(ranged.sphere_attributes.colors[0], 1.0f);  // 300 -> below: white
    EXPECT_EQ(ranged.sphere_attributes.colors[6], 0.0f);  // 400 -> above: black
}

TEST(SphereStyling, CategoricalColourByGivesEachCategoryItsPaletteColour) {
    Scene scene = particles();
    SphereStyleOptions options;
    options.color_by = "element";
    EXPECT_FALSE(apply_sphere_styling(scene, options, "md.ply").color_range);
    const std::vector<float>& colors = scene.sphere_attributes.colors;
    for (int c = 0; c < 3; ++c) {
        EXPECT_FLOAT_EQ(colors[c], linear(category_display_color("element", 0, "C")[c]));
        EXPECT_FLOAT_EQ(colors[3 + c], linear(category_display_color("element", 1, "O")[c]));
        EXPECT_EQ(colors[6 + c], colors[c]);  // C again
        EXPECT_FLOAT_EQ(colors[9 + c], linear(category_display_color("element", 2, "Fe")[c]));
    }
    EXPECT_NE(colors[0], colors[3]);
}

TEST(SphereStyling, RadiusByScaleAndMaterial) {
    Scene scene = particles();
    SphereStyleOptions options;
    options.radius_by = "temperature";
    options.radius_range = {0.1, 0.3};
    options.radius_scale = 2;
    options.material = MaterialPreset::Metal;
    apply_sphere_styling(scene, options, "md.ply");
    EXPECT_DOUBLE_EQ(scene.spheres[0].radius, 0.2);   // 300 -> 0.1, times 2
    EXPECT_DOUBLE_EQ(scene.spheres[2].radius, 0.6);   // 400 -> 0.3, times 2
    EXPECT_DOUBLE_EQ(scene.spheres[3].radius, 0.3);   // 325 -> 0.15, times 2
    EXPECT_EQ(scene.spheres[4].radius, 2);            // the light keeps its size
    EXPECT_EQ(scene.materials[0].type, MaterialType::Pbr);
    EXPECT_EQ(scene.materials[0].metallic, 1);
    EXPECT_EQ(scene.materials[0].color, (Vec3{0.8, 0.8, 0.8}));
    EXPECT_EQ(scene.materials[1].type, MaterialType::Diffuse);  // nor its material
    validate_scene(scene, "md.ply");
}

TEST(SphereStyling, ErrorsNameTheOptionAndWhatTheSceneHas) {
    SphereStyleOptions options;
    options.color_by = "temp";
    EXPECT_EQ(styling_error(particles(), options),
              "md.ply: --color-by temp: no such sphere property (the scene has: temperature, element)");
    Scene bare = particles();
    bare.sphere_attributes = {};
    EXPECT_EQ(styling_error(bare, options),
              "md.ply: --color-by temp: no such sphere property (the scene has no per-sphere properties)");
    options = {};
    options.radius_by = "element";
    options.radius_range = {1, 2};
    EXPECT_EQ(styling_error(particles(), options),
              "md.ply: --radius-by element: a categorical property (labels such as \"C\") has no size order; use a "
              "numeric property");
    options.radius_range.reset();
    options.radius_by = "temperature";
    EXPECT_EQ(styling_error(particles(), options), "md.ply: --radius-by temperature needs --radius-range MIN,MAX");
    options = {};
    options.radius_scale = 1e30;  // past the scene's float limits
    EXPECT_NE(styling_error(particles(), options).find("md.ply: spheres[0].radius: must be"), std::string::npos);
}

}  // namespace
}  // namespace orb
