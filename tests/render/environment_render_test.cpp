// Rendering under the environment light against closed forms. Tolerances:
// 5 standard errors of the mean over pixels, from the film's own sums of
// squares (radiance_sq), plus the rounding of float sums over n samples.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render_test_support.h"

namespace orb::render::test {
namespace {

constexpr double kSigmas = 5.0;

// A mean of n samples of `value`: its float arithmetic (n * 2^-24 of it at
// most) and each sample rounded to the film's units (2^-25 at most).
double float_rounding_bound(double value, std::uint64_t samples)
{
    return std::abs(value) * static_cast<double>(samples) * std::ldexp(1.0, -24) + std::ldexp(1.0, -25);
}

// The mean over `pixels` of (pixel mean radiance - expected(pixel)) is 0
// within kSigmas standard errors, in each channel.
template <typename Expected>
void expect_pixels_match(const Film& film, const std::vector<std::size_t>& pixels, Expected expected,
                         const std::string& what)
{
    ASSERT_FALSE(pixels.empty()) << what;
    const double n = static_cast<double>(film.samples_per_pixel);
    for (int c = 0; c < 3; ++c) {
        double difference = 0, rounding = 0;
        for (std::size_t p : pixels) {
            const double e = expected(p)[c];
            difference += film::sum_value(film::Units::Fixed, film.radiance[p * 3 + c]) / n - e;
            rounding += float_rounding_bound(e, film.samples_per_pixel);
        }
        const double count = static_cast<double>(pixels.size());
        const PixelStatistics s = radiance_statistics(film, pixels, c);
        EXPECT_NEAR(difference / count, 0.0, kSigmas * s.standard_error + rounding / count)
            << what << ", channel " << c << ": " << s.pixels << " pixels, standard error " << s.standard_error;
    }
}

void expect_mean_radiance(const Film& film, const std::vector<std::size_t>& pixels, const Vec3& expected,
                          const std::string& what)
{
    expect_pixels_match(film, pixels, [&](std::size_t) { return expected; }, what);
}

Camera looking_at(Vec3 position, Vec3 target, double vfov_deg)
{
    Camera camera;
    camera.position = position;
    camera.target = target;
    camera.vfov_deg = vfov_deg;
    return camera;
}

Vec3 times(const Vec3& a, const Vec3& b) { return {a[0] * b[0], a[1] * b[1], a[2] * b[2]}; }

Environment uniform(const Vec3& radiance)
{
    Environment e;
    e.kind = EnvironmentKind::Color;
    e.color = radiance;
    return e;
}

// A width x height map whose every texel is `texel`.
Environment constant_map(int width, int height, const Vec3& texel, double intensity, double rotation_deg)
{
    auto image = std::make_shared<EnvironmentImage>();
    image->width = width;
    image->height = height;
    for (int i = 0; i < width * height; ++i)
        for (double c : texel) image->rgb.push_back(static_cast<float>(c));
    Environment e;
    e.kind = EnvironmentKind::Map;
    e.map = "constant.exr";
    e.intensity = intensity;
    e.rotation_deg = rotation_deg;
    e.image = image;
    return e;
}

// Pixels whose centre ray missed everything, together with all 8
// neighbours (so no jittered sample of the pixel can have hit a sphere).
std::vector<std::size_t> missed_pixels(const Film& film)
{
    return interior_pixels_of(film, -1);
}

// A camera ray that escapes sees the environment's radiance, all of it in
// the emission set, with alpha 0 (coverage of spheres); every sample of
// such a pixel is the same, so the sums hold n times it up to rounding.
void expect_background(const Film& film, const Vec3& radiance, const std::string& what)
{
    const std::vector<std::size_t> missed = missed_pixels(film);
    ASSERT_GT(missed.size(), 50u) << what;
    const double n = static_cast<double>(film.samples_per_pixel);
    for (std::size_t p : missed) {
        for (int c = 0; c < 3; ++c) {
            const double tolerance = float_rounding_bound(radiance[c], film.samples_per_pixel);
            ASSERT_NEAR(film::sum_value(film::Units::Fixed, film.radiance[p * 3 + c]) / n, radiance[c], tolerance)
                << what << ", pixel " << p;
            ASSERT_NEAR(film::sum_value(film::Units::Fixed, film.emission[p * 3 + c]) / n, radiance[c], tolerance)
                << what << ", pixel " << p;
        }
        ASSERT_EQ(film.alpha[p], 0.0f) << what << ", pixel " << p;
        ASSERT_EQ(film.albedo[p * 3], 0.0f) << what << ", pixel " << p;
        // The background layer holds what alpha does not cover: here, all of it.
        for (int c = 0; c < 3; ++c) ASSERT_EQ(film.background[p * 3 + c], film.radiance[p * 3 + c]) << what;
    }
}

// A diffuse ball of albedo a under an environment of uniform radiance L
// reflects exactly a * L: its whole hemisphere sees L, and a convex ball
// never sees itself, so light scatters off it once, in both modes.
class BallUnderUniformEnvironment : public ::testing::TestWithParam<IntegratorMode> {};

Scene ball_under(const Environment& environment, const Vec3& albedo, MaterialType type = MaterialType::Diffuse)
{
    Scene scene;
    add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, type, albedo));
    scene.camera = looking_at({0, 0, 3.5}, {0, 0, 0}, 40.0);
    scene.environment = environment;
    return scene;
}

TEST_P(BallUnderUniformEnvironment, BallIsAlbedoTimesRadiance)
{
    const Vec3 albedo{0.5, 0.3, 0.8};
    const Vec3 sky{1.0, 2.0, 0.5};
    const Film film = render(ball_under(uniform(sky), albedo), small_config(32, 32, 11, 6, GetParam()), {64, 64});
    const std::vector<std::size_t> pixels = interior_pixels_of(film, 0);
    ASSERT_GT(pixels.size(), 200u);
    expect_mean_radiance(film, pixels, times(albedo, sky), "ball");
    for (std::size_t p : pixels) {
        EXPECT_EQ(film.indirect[p * 3], 0.0f);  // one diffuse vertex: direct light
        EXPECT_EQ(film.emission[p * 3], 0.0f);
        EXPECT_EQ(film.alpha[p], 128.0f);  // 128 samples, every one covered
    }
    expect_background(film, sky, "background");
}

// The background layer is the environment seen by camera rays that hit
// nothing: under a uniform sky L each such sample adds exactly L, so every
// pixel, the ball's edges included, holds (n - alpha) L, and RGB - background
// is the ball's own colour premultiplied by its coverage. Sums of equal
// values round by at most n ulps of the total.
TEST_P(BallUnderUniformEnvironment, BackgroundIsTheSkyWhereTheBallDoesNotCover)
{
    const Vec3 sky{1.0, 2.0, 0.5};
    const Film film = render(ball_under(uniform(sky), {0.5, 0.3, 0.8}), small_config(32, 32, 5, 6, GetParam()), {64});
    const double n = static_cast<double>(film.samples_per_pixel);
    std::size_t edges = 0;
    for (std::size_t p = 0; p < film.alpha.size(); ++p) {
        const double uncovered = n - static_cast<double>(film.alpha[p]);
        if (film.alpha[p] > 0 && uncovered > 0.0) ++edges;
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(film::sum_value(film::Units::Fixed, film.background[p * 3 + c]), uncovered * sky[c],
                        float_rounding_bound(n * sky[c], film.samples_per_pixel))
                << "pixel " << p << ", coverage " << static_cast<double>(film.alpha[p]) / n;
    }
    EXPECT_GT(edges, 20u) << "the ball's edge pixels, partly covered";
}

// A constant map is the same light as the uniform colour, whatever its
// size, intensity and rotation: the sin(theta) weighting of its rows and
// the density of its texels must cancel exactly.
TEST_P(BallUnderUniformEnvironment, AConstantMapGivesTheUniformColoursAnswer)
{
    const Vec3 albedo{0.5, 0.3, 0.8};
    const Vec3 sky{1.0, 2.0, 0.5};
    const Environment map = constant_map(16, 8, {0.25, 0.5, 0.125}, 4.0, 37.0);  // 4 x texel = sky
    const RenderConfig config = small_config(32, 32, 11, 6, GetParam());
    const Film with_map = render(ball_under(map, albedo), config, {64, 64});
    const std::vector<std::size_t> pixels = interior_pixels_of(with_map, 0);
    ASSERT_GT(pixels.size(), 200u);
    expect_mean_radiance(with_map, pixels, times(albedo, sky), "ball under a constant map");
    expect_background(with_map, sky, "background of the constant map");
}

INSTANTIATE_TEST_SUITE_P(Modes, BallUnderUniformEnvironment,
                         ::testing::Values(IntegratorMode::Global, IntegratorMode::Direct));

// Specular chains reach the environment with weight 1: a white mirror ball
// and a clear glass ball under a uniform sky show exactly the sky.
class SpecularBallUnderUniformEnvironment : public ::testing::TestWithParam<MaterialType> {};

TEST_P(SpecularBallUnderUniformEnvironment, ShowsTheSkyAsEmission)
{
    const Vec3 sky{1.0, 2.0, 0.5};
    const Film film = render(ball_under(uniform(sky), {1, 1, 1}, GetParam()), small_config(32, 32, 13, 64), {64, 64});
    const std::vector<std::size_t> pixels = interior_pixels_of(film, 0);
    ASSERT_GT(pixels.size(), 200u);
    expect_mean_radiance(film, pixels, sky, "specular ball");
    for (std::size_t p : pixels) {
        EXPECT_EQ(film.direct[p * 3 + 1], 0.0f);
        EXPECT_EQ(film.indirect[p * 3 + 1], 0.0f);
        EXPECT_EQ(film.alpha[p], 128.0f);
    }
}

INSTANTIATE_TEST_SUITE_P(Materials, SpecularBallUnderUniformEnvironment,
                         ::testing::Values(MaterialType::Mirror, MaterialType::Dielectric));

// ---- one bright texel: a small distant light ----

constexpr int kMapWidth = 32, kMapHeight = 16;
constexpr int kSunColumn = 20, kSunRow = 5;  // u in [0.625, 0.656), theta in [56.25, 67.5) degrees
constexpr double kSunRotationDeg = 30.0;

Environment sun_map(const Vec3& texel)
{
    Environment e = constant_map(kMapWidth, kMapHeight, {0, 0, 0}, 2.0, kSunRotationDeg);
    auto image = std::make_shared<EnvironmentImage>(*e.image);
    for (int c = 0; c < 3; ++c)
        image->rgb[std::size_t(3 * (kSunRow * kMapWidth + kSunColumn) + c)] = static_cast<float>(texel[c]);
    e.image = image;
    return e;
}

// The integral of the direction over the texel, V = ∫ w dw, in world space:
// a diffuse point of albedo a and normal n that sees the whole texel (n.w > 0
// over all of it) reflects (a / pi) L (n . V). In the map's frame a direction
// is (sin t cos p, cos t, sin t sin p) with p = 2 pi u - pi, and
// dw = sin t dt dp; the frame is turned about +y by the rotation.
Vec3 texel_direction_integral(int column, int row, int width, int height, double rotation_deg)
{
    const double pi = std::numbers::pi;
    const double t0 = pi * row / height, t1 = pi * (row + 1) / height;
    const double p0 = 2 * pi * column / width - pi, p1 = 2 * pi * (column + 1) / width - pi;
    const double sin2_integral = 0.5 * (t1 - t0) - 0.25 * (std::sin(2 * t1) - std::sin(2 * t0));
    const double mx = sin2_integral * (std::sin(p1) - std::sin(p0));
    const double my = 0.5 * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)) * (p1 - p0);
    const double mz = sin2_integral * (std::cos(p0) - std::cos(p1));
    const double a = rotation_deg * pi / 180.0;
    return {std::cos(a) * mx + std::sin(a) * mz, my, -std::sin(a) * mx + std::cos(a) * mz};
}

class BallUnderOneBrightTexel : public ::testing::TestWithParam<IntegratorMode> {};

TEST_P(BallUnderOneBrightTexel, IsLitLikeADistantLightFromTheTexelsDirection)
{
    const Vec3 albedo{0.8, 0.6, 0.4};
    const Vec3 texel{300.0, 200.0, 100.0};
    const double intensity = 2.0;
    Scene scene = ball_under(sun_map(texel), albedo);
    const int size = 48;
    const Film film = render(scene, small_config(size, size, 29, 6, GetParam()), {64, 64});
    const std::vector<std::size_t> ball = interior_pixels_of(film, 0);
    ASSERT_GT(ball.size(), 600u);

    const Vec3 v = texel_direction_integral(kSunColumn, kSunRow, kMapWidth, kMapHeight, kSunRotationDeg);
    const double solid_angle = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);  // |V| ~ the texel's solid angle
    const Vec3 towards_sun{v[0] / solid_angle, v[1] / solid_angle, v[2] / solid_angle};
    // The texel spans 11.25 degrees each way: a normal with n . w_sun > 0.35
    // (within 69.5 degrees) sees all of it, one with n . w_sun < -0.35 none.
    const auto mean_normal = [&](std::size_t p) {
        const double n = static_cast<double>(film.samples_per_pixel);
        const auto value = [&](std::size_t k) { return film::sum_value(film::Units::SignedFixed, film.normal[k]) / n; };
        return Vec3{value(p * 3), value(p * 3 + 1), value(p * 3 + 2)};
    };
    const auto facing = [&](std::size_t p) {
        const Vec3 n = mean_normal(p);
        return n[0] * towards_sun[0] + n[1] * towards_sun[1] + n[2] * towards_sun[2];
    };
    std::vector<std::size_t> lit, dark;
    for (std::size_t p : ball) {
        if (facing(p) > 0.35) lit.push_back(p);
        if (facing(p) < -0.35) dark.push_back(p);
    }
    // The sun is up and to the front right of the camera (+x, +y, +z with the
    // 30 degree turn), so the lit pixels lie in the upper right of the image.
    ASSERT_GT(lit.size(), 150u);
    ASSERT_GT(dark.size(), 20u);
    double lit_x = 0, lit_y = 0;
    for (std::size_t p : lit) {
        lit_x += double(p % size) / lit.size();
        lit_y += double(p / size) / lit.size();
    }
    EXPECT_GT(lit_x, 0.55 * size);
    EXPECT_LT(lit_y, 0.45 * size);
    EXPECT_GT(towards_sun[0], 0.3);
    EXPECT_GT(towards_sun[1], 0.3);
    EXPECT_GT(towards_sun[2], 0.3);

    // Radiance is linear in the normal where the whole texel is visible, so
    // a pixel's mean is (a / pi) L (n_mean . V) with n_mean the mean of its
    // samples' normals (the film's normal set).
    expect_pixels_match(
        film, lit,
        [&](std::size_t p) {
            const Vec3 n = mean_normal(p);
            const double irradiance_per_radiance = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
            Vec3 e;
            for (int c = 0; c < 3; ++c) e[c] = albedo[c] / std::numbers::pi * intensity * texel[c] * irradiance_per_radiance;
            return e;
        },
        "lit side");
    for (std::size_t p : dark) EXPECT_EQ(film.radiance[p * 3], 0.0f) << "pixel " << p % size << ", " << p / size;
}

INSTANTIATE_TEST_SUITE_P(Modes, BallUnderOneBrightTexel,
                         ::testing::Values(IntegratorMode::Global, IntegratorMode::Direct));

// With no sphere in view, every pixel sees the texel its ray points at, the
// map turned as documented: on an 8 x 4 map, the direction (1, 0.2, 0.05)
// is texel (4, 1) unturned, and texel (2, 1) turned by -90 degrees (the
// map's centre then faces +z, and +x is a quarter of the width across, as
// in Mitsuba's layout).
TEST(EnvironmentSeenByTheCamera, ShowsTheTexelInTheRaysDirection)
{
    auto image = std::make_shared<EnvironmentImage>();
    image->width = 8;
    image->height = 4;
    for (int i = 0; i < 32; ++i) {
        image->rgb.push_back(float(i));
        image->rgb.push_back(float(100 + i));
        image->rgb.push_back(0.5f);
    }
    for (auto [rotation, texel] : {std::pair{0.0, 12}, std::pair{-90.0, 10}}) {
        Scene scene;
        scene.camera = looking_at({0, 0, 0}, {1, 0.2, 0.05}, 0.5);  // a narrow view inside one texel
        scene.environment.kind = EnvironmentKind::Map;
        scene.environment.map = "test.exr";
        scene.environment.intensity = 0.5;
        scene.environment.rotation_deg = rotation;
        scene.environment.image = image;
        for (IntegratorMode mode : {IntegratorMode::Global, IntegratorMode::Direct}) {
            const Film film = render(scene, small_config(12, 12, 3, 6, mode), {4});
            expect_background(film, {0.5 * texel, 0.5 * (100 + texel), 0.25},
                              "turned " + std::to_string(rotation));
        }
    }
}

}  // namespace
}  // namespace orb::render::test
