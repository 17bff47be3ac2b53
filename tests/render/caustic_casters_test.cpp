// Continuations aimed at glass and mirror balls (kernels/caustic_casters.cl):
// which spheres the host lists, that the mixture keeps every estimate
// unbiased (exact answers with casters present, and agreement with the
// program that does not aim), and that caustics get less noisy.
// Tolerances: 5 standard errors of the pixel mean, from the film's sums of
// squares, plus the rounding of float sums (as in analytic_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render_test_support.h"
#include "scene_layout.h"

namespace orb::render::test {
namespace {

constexpr double kSigmas = 5.0;

double rounding(double value, std::uint64_t samples) { return value * static_cast<double>(samples) * 0x1p-24; }

// The options (development knob) of a program that aims at no caster.
const std::string kNoAiming = [] {
    device::KernelFeatures unaimed;
    unaimed.caster_share = 0.0f;
    return device::kernel_feature_options(unaimed);
}();

// Mean over pixels of each pixel's variance of the mean, red channel.
double mean_variance_of_mean(const Film& film, const std::vector<std::size_t>& pixels)
{
    const double n = static_cast<double>(film.samples_per_pixel);
    double sum = 0;
    for (std::size_t p : pixels) {
        const double mean = film::sum_value(film::Units::Fixed, film.radiance[3 * p]) / n;
        const double variance =
            (film::sum_value(film::Units::Fixed, film.radiance_sq[3 * p]) / n - mean * mean) * n / (n - 1.0);
        sum += std::max(0.0, variance) / n;
    }
    return sum / static_cast<double>(pixels.size());
}

}  // namespace

TEST(CausticCasters, TheLayoutListsTheSpheresWithoutADensity)
{
    Scene scene;
    const auto ball = [&](MaterialType type, double roughness, double metallic, double x) {
        const std::uint32_t m = add_material(scene, type, {1, 1, 1});
        scene.materials[m].roughness = roughness;
        scene.materials[m].metallic = metallic;
        add_sphere(scene, {x, 0, 0}, 0.5 + 0.01 * x, m);
    };
    ball(MaterialType::Diffuse, 0, 0, 0);
    ball(MaterialType::Mirror, 0, 0, 1);
    ball(MaterialType::Dielectric, 0, 0, 2);
    ball(MaterialType::Dielectric, 0.3, 0, 3);  // rough glass has a density
    ball(MaterialType::Pbr, 0, 1, 4);           // a smooth metal is a mirror
    ball(MaterialType::Pbr, 0, 0, 5);           // a smooth coat over a diffuse base has a density
    ball(MaterialType::Pbr, 0.2, 1, 6);         // a rough metal has a density
    const SceneLayout layout = layout_scene(scene);
    ASSERT_EQ(layout.counts.caster_count, 3);
    ASSERT_EQ(layout.tables.casters.size(), 3u);
    const double xs[] = {1, 2, 4};
    for (int k = 0; k < 3; ++k) {
        EXPECT_FLOAT_EQ(layout.tables.casters[k].centre_radius.x, static_cast<float>(xs[k]));
        EXPECT_FLOAT_EQ(layout.tables.casters[k].centre_radius.w, static_cast<float>(0.5 + 0.01 * xs[k]));
    }

    // Past kMaxCausticCasters none are aimed at.
    for (std::size_t i = 0; i < kMaxCausticCasters; ++i) ball(MaterialType::Mirror, 0, 0, 10.0 + i);
    EXPECT_EQ(layout_scene(scene).counts.caster_count, 0);
}

// Lossless balls (a white diffuse one, a mirror, clear smooth glass, a
// smooth metal and a smooth white coat over a white base) under a uniform
// sky L: light is neither absorbed nor created, so every pixel is L — with
// continuations aimed at the three casters among them, whose mixture weights
// must cancel exactly in expectation. Depth 64 makes paths cut short
// negligible.
TEST(CausticCasters, LosslessBallsUnderAUniformSkyLookLikeTheSky)
{
    const Vec3 sky{1.0, 2.0, 0.5};
    Scene scene;
    const auto ball = [&](MaterialType type, double metallic, Vec3 centre) {
        const std::uint32_t m = add_material(scene, type, {1, 1, 1});
        scene.materials[m].metallic = metallic;
        return add_sphere(scene, centre, 0.5, m);
    };
    ball(MaterialType::Diffuse, 0, {0, 0, 0});
    ball(MaterialType::Mirror, 0, {1.1, 0.2, 0});
    ball(MaterialType::Dielectric, 0, {-1.1, 0.1, 0.2});
    ball(MaterialType::Pbr, 1, {0.2, 1.1, -0.3});
    ball(MaterialType::Pbr, 0, {-0.3, -1.1, 0.1});
    scene.environment.kind = EnvironmentKind::Color;
    scene.environment.color = sky;
    scene.camera.position = {0, 0, 4.5};
    scene.camera.target = {0, 0, 0};
    scene.camera.vfov_deg = 45.0;
    ASSERT_EQ(layout_scene(scene).counts.caster_count, 3);

    const Film film = render(scene, small_config(32, 32, 11, 64), {64, 64});
    std::vector<std::size_t> pixels;
    for (int id = 0; id < 5; ++id) {
        const std::vector<std::size_t> ball_pixels = interior_pixels_of(film, id);
        EXPECT_GT(ball_pixels.size(), 10u) << "ball " << id;
        pixels.insert(pixels.end(), ball_pixels.begin(), ball_pixels.end());
    }
    for (int c = 0; c < 3; ++c) {
        const PixelStatistics s = radiance_statistics(film, pixels, c);
        const double l = sky[static_cast<std::size_t>(c)];
        EXPECT_NEAR(s.mean, l, kSigmas * s.standard_error + rounding(l, film.samples_per_pixel))
            << "channel " << c << ", " << s.pixels << " pixels";
    }
}

// A glass ball over a diffuse floor, lit by a small sphere light above it:
// the caustic under the ball is reached only by BSDF sampling. Aiming at the
// ball leaves the image's expectation unchanged (floor and ball pixels agree
// with the program that does not aim) and lowers the floor's noise: at this
// seed the mean variance of the floor's pixel means fell to 0.48 of the
// unaimed program's (the same seed's render is the same on every run).
TEST(CausticCasters, AimingAtAGlassBallKeepsTheImageAndLowersTheCausticsNoise)
{
    Scene scene;
    const int floor = add_sphere(scene, {0, -1000, 0}, 1000, add_material(scene, MaterialType::Diffuse, {0.75, 0.75, 0.75}));
    const int glass = add_sphere(scene, {0, 30, 0}, 15, add_material(scene, MaterialType::Dielectric, {0.9, 0.9, 0.9}));
    scene.materials[scene.spheres[static_cast<std::size_t>(glass)].material].ior = 1.5;
    add_sphere(scene, {0, 100, 0}, 15, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {15, 15, 15}));
    scene.camera.position = {20, 80, 160};
    scene.camera.target = {0, 20, 0};
    scene.camera.vfov_deg = 30.0;

    const RenderConfig config = small_config(64, 48, 17, 6);
    const Film aimed = render_with_cl_options(scene, config, {128, 128}, nullptr);
    const Film unaimed = render_with_cl_options(scene, config, {128, 128}, kNoAiming.c_str());
    for (int id : {floor, glass}) {
        const std::vector<std::size_t> pixels = interior_pixels_of(aimed, id);
        ASSERT_GT(pixels.size(), 50u) << "sphere " << id;
        for (int c = 0; c < 3; ++c) {
            const PixelStatistics a = radiance_statistics(aimed, pixels, c);
            const PixelStatistics u = radiance_statistics(unaimed, pixels, c);
            EXPECT_NEAR(a.mean, u.mean, kSigmas * std::hypot(a.standard_error, u.standard_error))
                << "sphere " << id << ", channel " << c;
        }
    }
    const std::vector<std::size_t> floor_pixels = interior_pixels_of(aimed, floor);
    EXPECT_LT(mean_variance_of_mean(aimed, floor_pixels), 0.7 * mean_variance_of_mean(unaimed, floor_pixels))
        << mean_variance_of_mean(aimed, floor_pixels) / mean_variance_of_mean(unaimed, floor_pixels);
}

// Direct mode counts no light that passed a caster after the first diffuse
// vertex, so its program carries no aiming: the same image, exactly, as the
// program built without it.
TEST(CausticCasters, DirectModeDoesNotAim)
{
    Scene scene;
    add_sphere(scene, {0, -1000, 0}, 1000, add_material(scene, MaterialType::Diffuse, {0.75, 0.75, 0.75}));
    add_sphere(scene, {0, 30, 0}, 15, add_material(scene, MaterialType::Dielectric, {0.9, 0.9, 0.9}));
    add_sphere(scene, {0, 100, 0}, 15, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {15, 15, 15}));
    scene.camera.position = {20, 80, 160};
    scene.camera.target = {0, 20, 0};
    scene.camera.vfov_deg = 30.0;
    ASSERT_EQ(layout_scene(scene).counts.caster_count, 1);
    const RenderConfig direct = small_config(32, 24, 5, 6, IntegratorMode::Direct);
    const Film built = render_with_cl_options(scene, direct, {16}, nullptr);
    const Film unaimed = render_with_cl_options(scene, direct, {16}, kNoAiming.c_str());
    EXPECT_EQ(built.radiance, unaimed.radiance);
    // In global mode the same scene's image does change.
    const RenderConfig global = small_config(32, 24, 5, 6, IntegratorMode::Global);
    EXPECT_NE(render_with_cl_options(scene, global, {16}, nullptr).radiance,
              render_with_cl_options(scene, global, {16}, kNoAiming.c_str()).radiance);
}

}  // namespace orb::render::test
