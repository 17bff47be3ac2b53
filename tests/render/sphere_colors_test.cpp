// Per-sphere colours (Scene::sphere_attributes.colors, ORB_SPHERE_COLORS):
// a sphere reflects its own colour instead of its material's, at every lane
// width of the CPU kernel and one path per work-item as on GPUs.
//  - A lone diffuse ball of colour a under a uniform environment L (a convex
//    ball never sees itself) looks exactly a*L: checked against 5 standard
//    errors of the pixel mean plus the packing's rounding of a.
//  - Twenty balls (enough for a BVH, so the records are in tree order), each
//    with its own colour and one shared white material, render the same film,
//    up to float rounding, as the same balls with one material of that colour
//    each: every layer, albedo included, reads the sphere's colour.
#include <gtest/gtest.h>

#include <cmath>

#include "render_test_support.h"
#include "scene_layout.h"

namespace orb::render::test {
namespace {

constexpr double kSigmas = 5.0;

// The colour the kernels read back from pack_sphere_color (device_types.h), in float as they compute it.
Vec3 unpacked(float red, float green, float blue)
{
    const std::uint32_t packed = pack_sphere_color(red, green, blue);
    const float r = static_cast<float>(packed & 2047u) * (1.0f / 2047.0f);
    const float g = static_cast<float>((packed >> 11) & 2047u) * (1.0f / 2047.0f);
    const float b = static_cast<float>(packed >> 22) * (1.0f / 1023.0f);
    return {r * r, g * g, b * b};
}

TEST(SphereColors, PackingKeepsColoursWithinItsBound)
{
    for (float c : {0.0f, 1e-4f, 0.01f, 0.2f, 0.5f, 0.73f, 1.0f}) {
        const Vec3 back = unpacked(c, c, c);
        // |sqrt error| <= 1/(2*max): relative error of c at most 2/(2*max*sqrt(c)) (plus its square).
        for (int k = 0; k < 3; ++k) {
            const double max = k < 2 ? 2047 : 1023;
            const double bound = std::sqrt(c) / max + 1 / (4 * max * max) + 1e-7;
            EXPECT_NEAR(back[static_cast<std::size_t>(k)], c, bound) << "component " << k << " of " << c;
        }
    }
    EXPECT_EQ(unpacked(0, 0, 0), (Vec3{0, 0, 0}));
    EXPECT_EQ(unpacked(1, 1, 1), (Vec3{1, 1, 1}));
}

class SphereColorLanes : public ::testing::TestWithParam<const char*> {};

TEST_P(SphereColorLanes, ABallUnderAUniformSkyLooksItsColourTimesTheSky)
{
    const Vec3 sky{1.0, 2.0, 0.5};
    const float color[3] = {0.2f, 0.5f, 0.9f};
    Scene scene;
    const int id = add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, MaterialType::Diffuse, {1, 1, 1}));
    scene.sphere_attributes.colors.assign(color, color + 3);
    scene.environment.kind = EnvironmentKind::Color;
    scene.environment.color = sky;
    scene.camera.position = {0, 0, 3.5};
    scene.camera.target = {0, 0, 0};
    scene.camera.vfov_deg = 40.0;
    const Film film = render_with_simd_lanes(scene, small_config(32, 32, 11, 8), {64, 64}, GetParam());
    const std::vector<std::size_t> pixels = interior_pixels_of(film, id);
    ASSERT_GT(pixels.size(), 200u);
    const Vec3 device_color = unpacked(color[0], color[1], color[2]);
    for (int c = 0; c < 3; ++c) {
        const auto k = static_cast<std::size_t>(c);
        const PixelStatistics s = radiance_statistics(film, pixels, c);
        const double expected = device_color[k] * sky[k];
        const double rounding = sky[k] * static_cast<double>(film.samples_per_pixel) * 0x1p-24;
        EXPECT_NEAR(s.mean, expected, kSigmas * s.standard_error + rounding) << "channel " << c;
        // Not the material's white: far outside the noise.
        EXPECT_LT(s.mean, 0.95 * sky[k]) << "channel " << c;
    }
}

TEST_P(SphereColorLanes, SphereColoursRenderAsMaterialsOfThoseColours)
{
    Scene coloured;
    const std::uint32_t white = add_material(coloured, MaterialType::Diffuse, {1, 1, 1});
    Scene materials;
    for (int i = 0; i < 20; ++i) {
        const Vec3 centre{(i % 5) - 2.0, (i / 5) - 1.5, 0.0};
        const float rgb[3] = {0.05f + 0.045f * static_cast<float>(i), 0.9f - 0.04f * static_cast<float>(i),
                              i % 2 ? 0.7f : 0.15f};
        add_sphere(coloured, centre, 0.45, white);
        coloured.sphere_attributes.colors.insert(coloured.sphere_attributes.colors.end(), rgb, rgb + 3);
        add_sphere(materials, centre, 0.45, add_material(materials, MaterialType::Diffuse, unpacked(rgb[0], rgb[1], rgb[2])));
    }
    for (Scene* scene : {&coloured, &materials}) {
        // A floor and a light, so that paths bounce between balls, floor and light.
        add_sphere(*scene, {0, -1e4 - 2.5, 0}, 1e4, add_material(*scene, MaterialType::Diffuse, unpacked(0.6f, 0.6f, 0.6f)));
        add_sphere(*scene, {-3, 6, 4}, 1.5, add_material(*scene, MaterialType::Diffuse, {0, 0, 0}, {8, 8, 8}));
        scene->camera.position = {0, 1, 7};
        scene->camera.target = {0, 0, 0};
    }
    // The floor's and the light's colours for the coloured scene: the material's (as packed).
    const float floor_and_light[6] = {0.6f, 0.6f, 0.6f, 0, 0, 0};
    coloured.sphere_attributes.colors.insert(coloured.sphere_attributes.colors.end(), floor_and_light, floor_and_light + 6);
    const RenderConfig config = small_config(24, 16, 3, 6);
    const Film a = render_with_simd_lanes(coloured, config, {4}, GetParam());
    const Film b = render_with_simd_lanes(materials, config, {4}, GetParam());
    expect_same_films_up_to_rounding(a, b);
}

INSTANTIATE_TEST_SUITE_P(Widths, SphereColorLanes, ::testing::Values("0", "16"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                             return std::string("lanes_") + (std::string(info.param) == "0" ? "1" : info.param);
                         });

}  // namespace
}  // namespace orb::render::test
