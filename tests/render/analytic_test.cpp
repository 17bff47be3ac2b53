// Rendered values against closed forms. Tolerances: 5 standard errors of the
// mean over pixels, computed from the film's own sums of squares, plus the
// rounding of float sums over n samples (n * 2^-24 relative).
#include <gtest/gtest.h>

#include <cmath>

#include "render_test_support.h"

namespace orb::render::test {
namespace {

constexpr double kSigmas = 5.0;

// A mean of n samples of `expected`: its float arithmetic (n * 2^-24 of it at
// most) and each sample rounded to the film's units (2^-25 at most).
double float_rounding_bound(double expected, std::uint64_t samples)
{
    return std::abs(expected) * static_cast<double>(samples) * std::ldexp(1.0, -24) + std::ldexp(1.0, -25);
}

void expect_mean_radiance(const Film& film, const std::vector<std::size_t>& pixels, const Vec3& expected,
                          const std::string& what)
{
    ASSERT_FALSE(pixels.empty()) << what;
    for (int c = 0; c < 3; ++c) {
        const PixelStatistics s = radiance_statistics(film, pixels, c);
        const double tolerance = kSigmas * s.standard_error + float_rounding_bound(expected[c], film.samples_per_pixel);
        EXPECT_NEAR(s.mean, expected[c], tolerance)
            << what << ", channel " << c << ": " << s.pixels << " pixels, standard error " << s.standard_error;
    }
}

Camera looking_at(Vec3 position, Vec3 target, double vfov_deg)
{
    Camera camera;
    camera.position = position;
    camera.target = target;
    camera.vfov_deg = vfov_deg;
    return camera;
}

// A grey diffuse ball inside a black sphere that emits Le everywhere: the
// ball reflects a * Le (its whole hemisphere sees Le), in both modes.
class BallInEmittingEnclosure : public ::testing::TestWithParam<IntegratorMode> {};

TEST_P(BallInEmittingEnclosure, BallRadianceIsAlbedoTimesEmission)
{
    const Vec3 albedo{0.5, 0.3, 0.8};
    const Vec3 le{1.0, 2.0, 0.5};
    Scene scene;
    const int ball = add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, MaterialType::Diffuse, albedo));
    add_sphere(scene, {0, 0, 0}, 5.0, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, le));
    scene.camera = looking_at({0, 0, 3.5}, {0, 0, 0}, 40.0);

    const Film film = render(scene, small_config(32, 32, 11, 6, GetParam()), {64, 64});
    const std::vector<std::size_t> pixels = interior_pixels_of(film, ball);
    ASSERT_GT(pixels.size(), 200u);
    expect_mean_radiance(film, pixels, {albedo[0] * le[0], albedo[1] * le[1], albedo[2] * le[2]}, "ball");
    // Light that scattered once off the ball is direct light.
    for (std::size_t p : pixels) {
        EXPECT_EQ(film.indirect[p * 3], 0.0f);
        EXPECT_EQ(film.emission[p * 3], 0.0f);
    }
}

INSTANTIATE_TEST_SUITE_P(Modes, BallInEmittingEnclosure,
                         ::testing::Values(IntegratorMode::Global, IntegratorMode::Direct));

// Inside a closed diffuse sphere of albedo a that emits Le: light scattered
// at most d times gives Le * (1 + a + ... + a^d) = Le (1 - a^(d+1)) / (1 - a).
Scene closed_emitting_sphere(const Vec3& albedo, const Vec3& le)
{
    Scene scene;
    add_sphere(scene, {0, 0, 0}, 2.0, add_material(scene, MaterialType::Diffuse, albedo, le));
    scene.camera = looking_at({0.3, -0.2, 0.5}, {1, 0.4, -1}, 60.0);
    return scene;
}

double furnace_global(double le, double a, int depth) { return le * (1.0 - std::pow(a, depth + 1)) / (1.0 - a); }

class ClosedSphereGlobal : public ::testing::TestWithParam<int> {};

TEST_P(ClosedSphereGlobal, MatchesGeometricSeriesOfDepth)
{
    const int depth = GetParam();
    const Vec3 albedo{0.5, 0.3, 0.7};
    const Vec3 le{1.0, 2.0, 0.5};
    const Film film = render(closed_emitting_sphere(albedo, le), small_config(32, 32, 3, depth), {128, 128});
    Vec3 expected{};
    for (int c = 0; c < 3; ++c) expected[c] = furnace_global(le[c], albedo[c], depth);
    expect_mean_radiance(film, all_pixels(film), expected, "depth " + std::to_string(depth));

    // The test must be able to tell depth d from d + 1, at least in the
    // channel of highest albedo (its series converges slowest).
    const int c = 2;
    const double step = furnace_global(le[c], albedo[c], depth + 1) - expected[c];
    EXPECT_LT(kSigmas * radiance_statistics(film, all_pixels(film), c).standard_error, 0.5 * step);
}

INSTANTIATE_TEST_SUITE_P(Depths, ClosedSphereGlobal, ::testing::Values(0, 1, 2, 3, 5));

TEST(ClosedSphere, LargeDepthApproachesLeOverOneMinusAlbedo)
{
    const Vec3 albedo{0.5, 0.3, 0.7};
    const Vec3 le{1.0, 2.0, 0.5};
    const int depth = 200;  // a^(d+1) is below 1e-30 for every channel
    const Film film = render(closed_emitting_sphere(albedo, le), small_config(32, 32, 5, depth), {128, 128});
    expect_mean_radiance(film, all_pixels(film),
                         {le[0] / (1 - albedo[0]), le[1] / (1 - albedo[1]), le[2] / (1 - albedo[2])}, "large depth");
}

TEST(ClosedSphere, DirectModeGivesEmissionPlusOneBounce)
{
    const Vec3 albedo{0.5, 0.3, 0.7};
    const Vec3 le{1.0, 2.0, 0.5};
    const Film film =
        render(closed_emitting_sphere(albedo, le), small_config(32, 32, 9, 6, IntegratorMode::Direct), {128, 128});
    expect_mean_radiance(film, all_pixels(film),
                         {le[0] * (1 + albedo[0]), le[1] * (1 + albedo[1]), le[2] * (1 + albedo[2])}, "direct mode");
    for (std::size_t p = 0; p < film.pixel_count(); ++p) EXPECT_EQ(film.indirect[p * 3], 0.0f);
}

// A diffuse plane (a radius-1e4 sphere, top at y = 0) lit by a sphere light
// of radius r centred at height h above the origin. A point p of the plane at
// distance d from the light's centre sees it as a cone with sin(theta) = r / d
// at angle alpha from the normal, cos(alpha) = h / d; the irradiance is
// pi * Le * sin^2(theta) * cos(alpha), so the radiance is
// a * Le * (r / d)^2 * (h / d) -- a * Le * (r / h)^2 directly below the light.
struct PlaneCase {
    double radius;
    double height;
    IntegratorMode mode;
    const char* simd_lanes;  // the CPU kernel (render_with_simd_lanes); nullptr: the default
};

class PlaneUnderSphereLight : public ::testing::TestWithParam<PlaneCase> {};

// Where the centre ray of pixel (x, y) meets the plane y = 0 (the camera model
// of docs/rendering.md: pinhole, vfov of the full height, top row first).
Vec3 plane_point_of_pixel(const Camera& camera, int width, int height, int x, int y)
{
    const auto normalized = [](Vec3 v) {
        const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return Vec3{v[0] / l, v[1] / l, v[2] / l};
    };
    const auto cross = [](Vec3 a, Vec3 b) {
        return Vec3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    const Vec3 forward = normalized({camera.target[0] - camera.position[0], camera.target[1] - camera.position[1],
                                     camera.target[2] - camera.position[2]});
    const Vec3 right = normalized(cross(forward, camera.up));
    const Vec3 up = cross(right, forward);
    const double half_h = std::tan(camera.vfov_deg * M_PI / 360.0), half_w = half_h * width / height;
    const double sx = (2.0 * (x + 0.5) / width - 1.0) * half_w, sy = (1.0 - 2.0 * (y + 0.5) / height) * half_h;
    Vec3 dir;
    for (int i = 0; i < 3; ++i) dir[i] = forward[i] + sx * right[i] + sy * up[i];
    const double t = -camera.position[1] / dir[1];
    return {camera.position[0] + t * dir[0], 0.0, camera.position[2] + t * dir[2]};
}

TEST_P(PlaneUnderSphereLight, MatchesClosedForm)
{
    const PlaneCase c = GetParam();
    const Vec3 albedo{0.8, 0.6, 0.4};
    const Vec3 le{2.0, 3.0, 4.0};
    Scene scene;
    const int plane = add_sphere(scene, {0, -1e4, 0}, 1e4, add_material(scene, MaterialType::Diffuse, albedo));
    add_sphere(scene, {0, c.height, 0}, c.radius, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, le));
    scene.camera = looking_at({0, 1, 3}, {0, 0, 0}, 2.0);  // a small patch around the point below the light

    const int size = 16;
    const Film film = render_with_simd_lanes(scene, small_config(size, size, 21, 6, c.mode), {256, 256}, c.simd_lanes);
    const std::vector<std::size_t> pixels = interior_pixels_of(film, plane);
    ASSERT_EQ(pixels.size(), 14u * 14u);
    // Over one pixel the closed form is close to linear, so the pixel mean is
    // its value at the pixel centre to well below the statistical tolerance.
    double mean_geometry = 0;  // mean over the pixels of (r/d)^2 (h/d)
    for (std::size_t p : pixels) {
        const Vec3 point = plane_point_of_pixel(scene.camera, size, size, static_cast<int>(p % size),
                                                static_cast<int>(p / size));
        const double d = std::sqrt(point[0] * point[0] + c.height * c.height + point[2] * point[2]);
        mean_geometry += (c.radius / d) * (c.radius / d) * (c.height / d) / static_cast<double>(pixels.size());
    }
    const double below = (c.radius / c.height) * (c.radius / c.height);
    EXPECT_NEAR(mean_geometry, below, 1e-2 * below);  // a sanity check that the view is centred below the light
    expect_mean_radiance(film, pixels,
                         {albedo[0] * le[0] * mean_geometry, albedo[1] * le[1] * mean_geometry,
                          albedo[2] * le[2] * mean_geometry},
                         "plane");
}

INSTANTIATE_TEST_SUITE_P(Lights, PlaneUnderSphereLight,
                         ::testing::Values(PlaneCase{1.0, 4.0, IntegratorMode::Global, nullptr},
                                           PlaneCase{0.1, 5.0, IntegratorMode::Global, nullptr},
                                           PlaneCase{2.0, 2.5, IntegratorMode::Global, nullptr},
                                           PlaneCase{1.0, 4.0, IntegratorMode::Direct, nullptr},
                                           // The CPU's kernels one by one (the default above is
                                           // the device's lane width on PoCL).
                                           PlaneCase{0.1, 5.0, IntegratorMode::Global, "0"},
                                           PlaneCase{0.1, 5.0, IntegratorMode::Global, "4"},
                                           PlaneCase{0.1, 5.0, IntegratorMode::Global, "8"},
                                           PlaneCase{0.1, 5.0, IntegratorMode::Global, "16"}));

// Many lights of different power, picked per vertex by power (the alias
// table): the plane's radiance is the sum of every light's closed form. 25
// small lights 1.5 apart at height 4 (in the BVH; the plane stays outside it),
// their radiances spread over 50x so the picking probabilities differ; no
// light hides another from the patch the camera sees.
class PlaneUnderManyLights : public ::testing::TestWithParam<IntegratorMode> {};

TEST_P(PlaneUnderManyLights, SumOfEveryLightsClosedForm)
{
    const Vec3 albedo{0.8, 0.6, 0.4};
    Scene scene;
    const int plane = add_sphere(scene, {0, -1e4, 0}, 1e4, add_material(scene, MaterialType::Diffuse, albedo));
    struct Light {
        Vec3 centre;
        double radius;
        Vec3 le;
    };
    std::vector<Light> lights;
    for (int i = 0; i < 25; ++i) {
        const double strength = 1.0 + 49.0 * ((i * 7) % 25) / 24.0;
        Light light{{1.5 * (i % 5 - 2), 4.0, 1.5 * (i / 5 - 2)}, 0.1 + 0.1 * ((i * 3) % 5) / 4.0,
                    {strength, 0.5 * strength, 0.25 * strength}};
        add_sphere(scene, light.centre, light.radius, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, light.le));
        lights.push_back(light);
    }
    scene.camera = looking_at({0, 1, 3}, {0, 0, 0}, 2.0);

    const int size = 16;
    const Film film = render(scene, small_config(size, size, 23, 6, GetParam()), {256, 256});
    const std::vector<std::size_t> pixels = interior_pixels_of(film, plane);
    ASSERT_EQ(pixels.size(), 14u * 14u);
    Vec3 expected{0, 0, 0};
    for (std::size_t p : pixels) {
        const Vec3 point = plane_point_of_pixel(scene.camera, size, size, static_cast<int>(p % size),
                                                static_cast<int>(p / size));
        for (const Light& light : lights) {
            const double dx = light.centre[0] - point[0], dy = light.centre[1], dz = light.centre[2] - point[2];
            const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
            const double geometry = (light.radius / d) * (light.radius / d) * (dy / d) / static_cast<double>(pixels.size());
            for (int c = 0; c < 3; ++c) expected[c] += albedo[c] * light.le[c] * geometry;
        }
    }
    expect_mean_radiance(film, pixels, expected, "plane under 25 lights");
}

INSTANTIATE_TEST_SUITE_P(Modes, PlaneUnderManyLights,
                         ::testing::Values(IntegratorMode::Global, IntegratorMode::Direct));

// Specular chains: a white mirror ball and a clear glass ball inside an
// emitting enclosure show exactly the enclosure's radiance (Fresnel
// reflection and transmission together conserve energy), all of it in the
// emission set.
class SpecularBallInEnclosure : public ::testing::TestWithParam<MaterialType> {};

TEST_P(SpecularBallInEnclosure, ShowsEnclosureRadianceAsEmission)
{
    const Vec3 le{1.0, 2.0, 0.5};
    Scene scene;
    const int ball = add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, GetParam(), {1, 1, 1}, {0, 0, 0}, 1.5));
    add_sphere(scene, {0, 0, 0}, 5.0, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, le));
    scene.camera = looking_at({0, 0, 3.5}, {0, 0, 0}, 40.0);

    const Film film = render(scene, small_config(32, 32, 13, 64), {64, 64});
    const std::vector<std::size_t> pixels = interior_pixels_of(film, ball);
    ASSERT_GT(pixels.size(), 200u);
    expect_mean_radiance(film, pixels, le, "specular ball");
    for (std::size_t p : pixels) {
        EXPECT_EQ(film.direct[p * 3 + 1], 0.0f);
        EXPECT_EQ(film.indirect[p * 3 + 1], 0.0f);
    }
}

INSTANTIATE_TEST_SUITE_P(Materials, SpecularBallInEnclosure,
                         ::testing::Values(MaterialType::Mirror, MaterialType::Dielectric));

}  // namespace
}  // namespace orb::render::test
