// White furnaces: a white ball inside a large black sphere that emits
// radiance L everywhere, or under the scene's uniform environment light L. A ball that neither absorbs
// nor loses energy looks exactly L; a rough one (single-scattering GGX has no
// energy compensation) loses a little and never gains. Tolerances: 5 standard
// errors of the pixel mean, from the film's own sums of squares, plus the
// rounding of float sums (as in analytic_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pbr_albedo_reference.h"
#include "pbr_albedo_table.h"
#include "render_test_support.h"

namespace orb::render::test {
namespace {

constexpr double kSigmas = 5.0;
const Vec3 kRadiance{1.0, 2.0, 0.5};

struct BallMaterial {
    MaterialType type;
    double roughness = 0;
    double metallic = 0;
};

struct FurnaceResult {
    PixelStatistics channel[3];
    std::uint64_t samples = 0;
};

enum class FurnaceLight { Enclosure, Environment };

FurnaceResult furnace(const BallMaterial& ball, IntegratorMode mode, int max_depth = 64, std::uint64_t seed = 5,
                      FurnaceLight light = FurnaceLight::Enclosure)
{
    Scene scene;
    const std::uint32_t white = add_material(scene, ball.type, {1, 1, 1});
    scene.materials[white].roughness = ball.roughness;
    scene.materials[white].metallic = ball.metallic;
    const int id = add_sphere(scene, {0, 0, 0}, 1.0, white);
    if (light == FurnaceLight::Enclosure) {
        add_sphere(scene, {0, 0, 0}, 5.0, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, kRadiance));
    } else {
        scene.environment.kind = EnvironmentKind::Color;
        scene.environment.color = kRadiance;
    }
    scene.camera.position = {0, 0, 3.5};
    scene.camera.target = {0, 0, 0};
    scene.camera.vfov_deg = 40.0;
    const Film film = render(scene, small_config(32, 32, seed, max_depth, mode), {64, 64});
    const std::vector<std::size_t> pixels = interior_pixels_of(film, id);
    EXPECT_GT(pixels.size(), 200u);
    FurnaceResult result;
    for (int c = 0; c < 3; ++c) result.channel[c] = radiance_statistics(film, pixels, c);
    result.samples = film.samples_per_pixel;
    return result;
}

double rounding(double value, std::uint64_t samples) { return value * static_cast<double>(samples) * 0x1p-24; }

// Each channel's mean / L lies in [low, high], widened by the noise.
void expect_ratio_within(const FurnaceResult& r, double low, double high, const std::string& what)
{
    for (int c = 0; c < 3; ++c) {
        const double l = kRadiance[static_cast<std::size_t>(c)];
        const double slack = kSigmas * r.channel[c].standard_error + rounding(l, r.samples);
        EXPECT_LE(r.channel[c].mean, high * l + slack) << what << ", channel " << c << " (gains energy)";
        EXPECT_GE(r.channel[c].mean, low * l - slack) << what << ", channel " << c;
    }
}

struct ExactCase {
    const char* name;
    BallMaterial material;
    IntegratorMode mode;
};

void PrintTo(const ExactCase& c, std::ostream* out) { *out << c.name; }

class LosslessBall : public ::testing::TestWithParam<ExactCase> {};

// Lambert, the mirror, smooth glass (enough depth for the light trapped
// inside), and the smooth pbr materials: a white metal reflects F = 1, and a
// white dielectric base receives exactly what its smooth coat does not
// reflect, 1 - F(cos), so both return L.
TEST_P(LosslessBall, LooksExactlyLikeTheEnvironment)
{
    const ExactCase& c = GetParam();
    expect_ratio_within(furnace(c.material, c.mode, 256), 1.0, 1.0, c.name);
}

INSTANTIATE_TEST_SUITE_P(
    Furnace, LosslessBall,
    ::testing::Values(ExactCase{"diffuse", {MaterialType::Diffuse}, IntegratorMode::Global},
                      ExactCase{"diffuse_direct", {MaterialType::Diffuse}, IntegratorMode::Direct},
                      ExactCase{"mirror", {MaterialType::Mirror}, IntegratorMode::Global},
                      ExactCase{"smooth_glass", {MaterialType::Dielectric}, IntegratorMode::Global},
                      ExactCase{"smooth_metal", {MaterialType::Pbr, 0.0, 1.0}, IntegratorMode::Global},
                      ExactCase{"smooth_plastic", {MaterialType::Pbr, 0.0, 0.0}, IntegratorMode::Global},
                      ExactCase{"smooth_plastic_direct", {MaterialType::Pbr, 0.0, 0.0}, IntegratorMode::Direct}),
    [](const ::testing::TestParamInfo<ExactCase>& info) { return info.param.name; });

// The same lossless balls lit by a uniform environment instead of the
// enclosure (the environment's next-event estimates, its MIS at escaped
// rays): on PoCL these render with the device's lanes, the enclosure's too.
TEST(LosslessBallUnderTheEnvironment, LooksExactlyLikeTheEnvironment)
{
    for (const ExactCase& c : {ExactCase{"diffuse", {MaterialType::Diffuse}, IntegratorMode::Global},
                               ExactCase{"mirror", {MaterialType::Mirror}, IntegratorMode::Global},
                               ExactCase{"smooth_glass", {MaterialType::Dielectric}, IntegratorMode::Global}})
        expect_ratio_within(furnace(c.material, c.mode, 256, 9, FurnaceLight::Environment), 1.0, 1.0, c.name);
}

// Roughnesses of the rough furnaces: a narrow lobe and a wide one.
class RoughBall : public ::testing::TestWithParam<double> {};

// A rough white metal reflects each direction's single-scattering GGX albedo
// E(cos) < 1: never more than L, never less than L times the smallest E
// (computed on the host, pbr_albedo_reference.cpp). Global and direct mode
// (light sampling of the enclosure with MIS) agree.
TEST_P(RoughBall, MetalLosesALittleAndNeverGains)
{
    const double roughness = GetParam();
    double smallest = 1;
    for (int i = 1; i <= 40; ++i) smallest = std::min(smallest, pbr_specular_albedo(i / 40.0, roughness, 128, 1.0));
    const FurnaceResult global = furnace({MaterialType::Pbr, roughness, 1.0}, IntegratorMode::Global);
    const FurnaceResult direct = furnace({MaterialType::Pbr, roughness, 1.0}, IntegratorMode::Direct, 6, 9);
    expect_ratio_within(global, smallest, 1.0, "global");
    expect_ratio_within(direct, smallest, 1.0, "direct");
    for (int c = 0; c < 3; ++c) {
        const double se = std::hypot(global.channel[c].standard_error, direct.channel[c].standard_error);
        EXPECT_NEAR(global.channel[c].mean, direct.channel[c].mean, kSigmas * se) << "channel " << c;
    }
}

// A white rough dielectric base loses at most the albedo table's margin.
TEST_P(RoughBall, PlasticLosesAtMostTheTablesMargin)
{
    const double margin = pbr_albedo_table().largest_raise;
    const BallMaterial plastic{MaterialType::Pbr, GetParam(), 0.0};
    expect_ratio_within(furnace(plastic, IntegratorMode::Global), 1.0 - margin, 1.0, "global");
    expect_ratio_within(furnace(plastic, IntegratorMode::Direct, 6, 9), 1.0 - margin, 1.0, "direct");
}

// Rough glass: light refracts in, scatters inside and out again; each GGX
// interaction loses a little to masking. Never more than L. (The lower bound
// only guards against a broken lobe: losing all transmission would leave
// about the 10% that the surface reflects.)
TEST_P(RoughBall, GlassLosesALittleAndNeverGains)
{
    const FurnaceResult r = furnace({MaterialType::Dielectric, GetParam(), 0.0}, IntegratorMode::Global, 256);
    expect_ratio_within(r, 0.5, 1.0, "rough glass");
}

// The same furnaces lit by the environment light instead of the enclosure
// (its own light sampling and MIS): the same bounds, and the same mean.
TEST_P(RoughBall, TheEnvironmentLightGivesTheEnclosuresFurnace)
{
    const double roughness = GetParam();
    double smallest = 1;
    for (int i = 1; i <= 40; ++i) smallest = std::min(smallest, pbr_specular_albedo(i / 40.0, roughness, 128, 1.0));
    struct Case {
        const char* name;
        BallMaterial material;
        IntegratorMode mode;
        int depth;
        double low;
    };
    for (const Case& c : {Case{"metal", {MaterialType::Pbr, roughness, 1.0}, IntegratorMode::Global, 64, smallest},
                          Case{"metal_direct", {MaterialType::Pbr, roughness, 1.0}, IntegratorMode::Direct, 6, smallest},
                          Case{"glass", {MaterialType::Dielectric, roughness, 0.0}, IntegratorMode::Global, 256, 0.5}}) {
        const FurnaceResult sky = furnace(c.material, c.mode, c.depth, 13, FurnaceLight::Environment);
        const FurnaceResult enclosure = furnace(c.material, c.mode, c.depth, 5, FurnaceLight::Enclosure);
        expect_ratio_within(sky, c.low, 1.0, c.name);
        for (int k = 0; k < 3; ++k) {
            const double se = std::hypot(sky.channel[k].standard_error, enclosure.channel[k].standard_error);
            EXPECT_NEAR(sky.channel[k].mean, enclosure.channel[k].mean, kSigmas * se) << c.name << ", channel " << k;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Furnace, RoughBall, ::testing::Values(0.15, 0.5));

}  // namespace
}  // namespace orb::render::test
