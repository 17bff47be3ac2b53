// The BSDFs of kernels/bsdf*.cl, called on the device through a probe kernel:
// sampling against the BSDF's own pdf (Pearson's chi-square over the sphere of
// directions, as pbrt's and Mitsuba's tests do), the weight a sample carries
// against eval / pdf, the pdf's integral, reciprocity, and energy (a white
// material reflects and transmits at most what it receives).
// ORB_BSDF_TEST_VERBOSE=1 prints each chi-square test's statistics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "bsdf_probe.h"
#include "chi2.h"
#include "pbr_albedo_reference.h"
#include "pbr_albedo_table.h"

namespace orb::render::test {
namespace {

using device::MaterialKind;

// The sphere of directions in bins of equal solid angle: cos(theta) in
// [-1, 1] and phi in [0, 2 pi), n = +z.
constexpr int kCosBins = 20;
constexpr int kPhiBins = 40;
constexpr int kBins = kCosBins * kPhiBins;
// Each bin is integrated with a midpoint rule in (theta, phi), fine enough in
// theta to resolve the narrowest lobe tested (roughness 0.3, alpha 0.09).
constexpr int kSubTheta = 48;
constexpr int kSubPhi = 12;
// Samples per chi-square test.
constexpr std::size_t kSamples = 4'000'000;
// The chance that any chi-square test below fails although every BSDF samples its pdf.
constexpr double kSignificance = 0.01;

int bin_of(const Dir& d)
{
    const int c = std::clamp(static_cast<int>((d[2] + 1.0) * 0.5 * kCosBins), 0, kCosBins - 1);
    double phi = std::atan2(d[1], d[0]);
    if (phi < 0) phi += 2 * std::numbers::pi;
    const int p = std::clamp(static_cast<int>(phi / (2 * std::numbers::pi) * kPhiBins), 0, kPhiBins - 1);
    return c * kPhiBins + p;
}

// The directions of the integration grid, with their bins and solid angles.
struct Grid {
    std::vector<Dir> directions;
    std::vector<int> bins;
    std::vector<double> solid_angles;
};

const Grid& integration_grid()
{
    static const Grid grid = [] {
        Grid g;
        const double pi = std::numbers::pi;
        for (int c = 0; c < kCosBins; ++c) {
            const double theta_hi = std::acos(std::clamp(-1.0 + 2.0 * c / kCosBins, -1.0, 1.0));
            const double theta_lo = std::acos(std::clamp(-1.0 + 2.0 * (c + 1) / kCosBins, -1.0, 1.0));
            const double dtheta = (theta_hi - theta_lo) / kSubTheta;
            for (int p = 0; p < kPhiBins; ++p)
                for (int i = 0; i < kSubTheta; ++i) {
                    const double theta = theta_lo + (i + 0.5) * dtheta;
                    for (int j = 0; j < kSubPhi; ++j) {
                        const double dphi = 2 * pi / (kPhiBins * kSubPhi);
                        const double phi = (p * kSubPhi + j + 0.5) * dphi;
                        g.directions.push_back(
                            {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
                        g.bins.push_back(c * kPhiBins + p);
                        g.solid_angles.push_back(std::sin(theta) * dtheta * dphi);
                    }
                }
        }
        return g;
    }();
    return grid;
}

BsdfProbe& probe()
{
    static BsdfProbe instance;
    return instance;
}

struct Case {
    std::string name;
    device::MaterialRecord material;
    double cos_o;
    bool outside = true;
    std::vector<device::CasterRecord> casters = {};  // the continuation's mixture aims at these too
};

device::MaterialRecord pbr(std::array<float, 3> color, float roughness, float metallic)
{
    return material_record(MaterialKind::Pbr, color, roughness, metallic);
}

device::MaterialRecord glass(float roughness, float ior = 1.5f)
{
    return material_record(MaterialKind::Dielectric, {1, 1, 1}, roughness, 0, ior);
}

std::string label(const std::string& kind, double roughness, double cos_o)
{
    std::ostringstream out;
    out << kind << "_r" << std::lround(roughness * 100) << "_cos" << std::lround(cos_o * 100);
    return out.str();
}

// Every non-delta BSDF the chi-square test covers: several roughnesses and
// incidences of each material, glass from both sides.
std::vector<Case> chi2_cases()
{
    std::vector<Case> cases;
    cases.push_back({"diffuse_cos70", material_record(MaterialKind::Diffuse, {0.5f, 0.6f, 0.7f}), 0.7});
    for (float r : {0.3f, 0.6f, 1.0f})
        for (double c : {0.95, 0.5, 0.15}) cases.push_back({label("metal", r, c), pbr({0.9f, 0.6f, 0.3f}, r, 1), c});
    for (float r : {0.3f, 1.0f})
        for (double c : {0.9, 0.3}) cases.push_back({label("plastic", r, c), pbr({0.8f, 0.3f, 0.2f}, r, 0), c});
    // Half metal and smooth: a delta lobe beside the diffuse one (only the latter has a density).
    cases.push_back({"smooth_half_metal_cos60", pbr({0.7f, 0.7f, 0.7f}, 0, 0.5f), 0.6});
    for (float r : {0.3f, 0.6f, 1.0f})
        for (double c : {0.9, 0.4}) {
            cases.push_back({label("glass_outside", r, c), glass(r), c, true});
            cases.push_back({label("glass_inside", r, c), glass(r), c, false});
        }
    return cases;
}

void PrintTo(const Case& c, std::ostream* out) { *out << c.name; }

class BsdfSampling : public ::testing::TestWithParam<Case> {};

// Samples the case (through the continuation's mixture when it has
// casters) and checks them against the density it reports: the weight is
// f |cos| / pdf, the pdf integrates to the share of samples with a density,
// and the directions follow it (chi-square, Sidak level over `tests` tests).
void expect_sampling_matches_pdf(const Case& c, int tests)
{
    const Dir wo = direction_at(c.cos_o);
    const std::vector<ProbeSample> samples = probe().sample(c.material, wo, c.outside, kSamples, 1234u, c.casters);

    std::vector<double> observed(kBins, 0.0);
    std::size_t with_density = 0;
    double worst_weight = 0, worst_pdf = 0;
    for (const ProbeSample& s : samples) {
        if (!s.valid || s.delta) continue;
        ++with_density;
        observed[static_cast<std::size_t>(bin_of(s.wi))] += 1.0;
        // The weight is f |cos| / pdf and the pdf is the one bsdf_eval reports.
        ASSERT_GT(s.eval_pdf, 0.0);
        for (std::size_t k = 0; k < 3; ++k) {
            const double expected = s.eval_f_cos[k] / s.eval_pdf;
            worst_weight = std::max(worst_weight, std::abs(s.weight[k] - expected) / std::max(1e-3, expected));
        }
        worst_pdf = std::max(worst_pdf, std::abs(s.pdf - s.eval_pdf) / s.eval_pdf);
    }
    EXPECT_LT(worst_weight, 1e-3) << "largest relative difference of weight and eval / pdf";
    EXPECT_LT(worst_pdf, 1e-4) << "largest relative difference of the sample's pdf and bsdf_pdf";
    ASSERT_GT(with_density, kSamples / 10) << "most samples must come from lobes with a density";

    const Grid& grid = integration_grid();
    const std::vector<ProbeEval> values = probe().eval(c.material, c.outside, wo, grid.directions, c.casters);
    std::vector<double> expected(kBins, 0.0);
    double integral = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        ASSERT_TRUE(values[i].pdf >= 0.0 && std::isfinite(values[i].pdf)) << "pdf " << values[i].pdf;
        const double mass = values[i].pdf * grid.solid_angles[i];
        expected[static_cast<std::size_t>(grid.bins[i])] += mass * kSamples;
        integral += mass;
    }

    // The pdf integrates to the share of samples it describes: 1 unless some
    // are lost (reflected below the surface) or come from a delta lobe.
    const double share = static_cast<double>(with_density) / kSamples;
    const double share_error = std::sqrt(share * (1 - share) / kSamples);
    constexpr double kIntegration = 2e-3;  // the midpoint rule's error on the grid above (measured: < 5e-4)
    EXPECT_NEAR(integral, share, 5 * share_error + kIntegration);
    EXPECT_LE(integral, 1.0 + kIntegration);

    const Chi2Result chi2 = pearson_chi2(observed, expected);
    if (std::getenv("ORB_BSDF_TEST_VERBOSE"))
        std::fprintf(stderr, "%s: p %.4f chi2 %.1f dof %d integral %.5f share %.5f weight %.2e pdf %.2e\n",
                     c.name.c_str(), chi2.p_value, chi2.statistic, chi2.dof, integral, share, worst_weight, worst_pdf);
    ASSERT_TRUE(chi2.problem.empty()) << chi2.problem;
    const double level = sidak_level(kSignificance, tests);
    EXPECT_GT(chi2.p_value, level) << "chi2 " << chi2.statistic << " with " << chi2.dof << " degrees of freedom";
}

TEST_P(BsdfSampling, MatchesItsPdfAndWeighsByEvalOverPdf)
{
    expect_sampling_matches_pdf(GetParam(), static_cast<int>(chi2_cases().size()));
}

// The continuation's mixture (kernels/caustic_casters.cl) at a vertex at the
// origin, n = +z: casters above the surface, one cut by the horizon, two
// whose cones overlap, one the vertex is inside of (a lost strategy), under
// a diffuse, a glossy, a smooth-coated (a delta lobe beside the density) and
// a rough glass BSDF (from inside, so aimed directions also transmit).
std::vector<Case> continuation_cases()
{
    const auto caster = [](float x, float y, float z, float r) { return device::CasterRecord{{x, y, z, r}}; };
    const std::vector<device::CasterRecord> one{caster(0.4f, 0.3f, 2.0f, 0.8f)};
    const std::vector<device::CasterRecord> horizon{caster(2.0f, -0.5f, 0.3f, 0.9f)};
    const std::vector<device::CasterRecord> overlapping{caster(0.4f, 0.3f, 2.0f, 0.8f), caster(0.9f, 0.2f, 2.5f, 1.0f),
                                                        caster(-1.5f, 1.0f, 0.5f, 0.4f)};
    const std::vector<device::CasterRecord> around{caster(0.0f, 0.0f, 0.5f, 1.0f), caster(-0.5f, 0.8f, 1.5f, 0.5f)};
    std::vector<Case> cases;
    const device::MaterialRecord diffuse = material_record(MaterialKind::Diffuse, {0.5f, 0.6f, 0.7f});
    cases.push_back({"diffuse_one_caster", diffuse, 0.7, true, one});
    cases.push_back({"diffuse_caster_at_the_horizon", diffuse, 0.7, true, horizon});
    cases.push_back({"diffuse_overlapping_casters", diffuse, 0.4, true, overlapping});
    cases.push_back({"diffuse_inside_a_caster", diffuse, 0.7, true, around});
    cases.push_back({"metal_r30_overlapping_casters", pbr({0.9f, 0.6f, 0.3f}, 0.3f, 1), 0.8, true, overlapping});
    cases.push_back({"smooth_half_metal_one_caster", pbr({0.7f, 0.7f, 0.7f}, 0, 0.5f), 0.6, true, one});
    cases.push_back({"glass_inside_r60_overlapping_casters", glass(0.6f), 0.9, false, overlapping});
    return cases;
}

class ContinuationSampling : public ::testing::TestWithParam<Case> {};

TEST_P(ContinuationSampling, MatchesTheMixturesPdfAndWeighsByEvalOverPdf)
{
    expect_sampling_matches_pdf(GetParam(), static_cast<int>(continuation_cases().size()));
}

INSTANTIATE_TEST_SUITE_P(Casters, ContinuationSampling, ::testing::ValuesIn(continuation_cases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

INSTANTIATE_TEST_SUITE_P(Bsdfs, BsdfSampling, ::testing::ValuesIn(chi2_cases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

TEST(BsdfSampling, DiffusePdfIntegratesToOne)
{
    const Grid& grid = integration_grid();
    const auto m = material_record(MaterialKind::Diffuse, {1, 1, 1});
    double integral = 0;
    const std::vector<ProbeEval> values = probe().eval(m, true, direction_at(0.3), grid.directions);
    for (std::size_t i = 0; i < values.size(); ++i) integral += values[i].pdf * grid.solid_angles[i];
    EXPECT_NEAR(integral, 1.0, 2e-3);
}

// Uniform directions on the hemisphere (or sphere), deterministic.
std::vector<Dir> spread_directions(int count, bool upper_only, unsigned seed)
{
    std::vector<Dir> out;
    std::uint32_t state = seed;
    const auto next = [&] {
        state = state * 1664525u + 1013904223u;
        return (state >> 8) * 0x1p-24;
    };
    while (static_cast<int>(out.size()) < count) {
        const double z = upper_only ? next() : 2 * next() - 1;
        const double phi = 2 * std::numbers::pi * next();
        const double r = std::sqrt(std::max(0.0, 1 - z * z));
        if (std::abs(z) < 0.05) continue;  // keep clear of grazing, where f's float error grows
        out.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    return out;
}

// f(wo, wi) = eval(wo, wi) / |cos wi|; reflection is symmetric in its two
// directions, and refraction obeys f(wi -> wo) / n_o^2 = f(wo -> wi) / n_i^2
// (Veach 1997, eq. 5.14): the radiance BTDF carries (n_o / n_i)^2.
TEST(BsdfReciprocity, ReflectionIsSymmetricAndRefractionScalesByTheIndices)
{
    const std::vector<device::MaterialRecord> materials{pbr({0.9f, 0.5f, 0.2f}, 0.3f, 1), pbr({0.8f, 0.3f, 0.2f}, 0.5f, 0),
                                                        pbr({1, 1, 1}, 1.0f, 0.3f), glass(0.3f), glass(0.8f, 1.33f),
                                                        material_record(MaterialKind::Diffuse, {0.5f, 0.5f, 0.5f})};
    const std::vector<Dir> a = spread_directions(2000, true, 7u);
    const std::vector<Dir> b = spread_directions(2000, false, 11u);
    for (const device::MaterialRecord& m : materials) {
        for (bool outside : {true, false}) {
            const std::vector<ProbeEval> forward = probe().eval(m, outside, a, b);
            // The reverse: wi becomes the viewer. A refraction's wi lies below, so
            // mirror both through the surface plane to keep the viewer above n = +z
            // (isotropic BSDFs do not change), and the viewer is on the other side.
            std::vector<Dir> ra, rb;
            std::vector<bool> transmitted;
            for (std::size_t k = 0; k < a.size(); ++k) {
                const bool t = b[k][2] < 0;
                transmitted.push_back(t);
                ra.push_back(t ? Dir{b[k][0], b[k][1], -b[k][2]} : b[k]);
                rb.push_back(t ? Dir{a[k][0], a[k][1], -a[k][2]} : a[k]);
            }
            const std::vector<ProbeEval> reverse_reflection = probe().eval(m, outside, ra, rb);
            const std::vector<ProbeEval> reverse_refraction = probe().eval(m, !outside, ra, rb);
            const double ior = m.ior;
            const double n_o = outside ? 1.0 : ior, n_i = outside ? ior : 1.0;
            int compared = 0;
            for (std::size_t k = 0; k < a.size(); ++k) {
                const ProbeEval& back = transmitted[k] ? reverse_refraction[k] : reverse_reflection[k];
                for (std::size_t c = 0; c < 3; ++c) {
                    const double f = forward[k].f_cos[c] / std::abs(b[k][2]);
                    double g = back.f_cos[c] / std::abs(a[k][2]);
                    if (transmitted[k]) g *= (n_o * n_o) / (n_i * n_i);
                    if (f < 1e-4 && g < 1e-4) continue;
                    ++compared;
                    ASSERT_NEAR(f, g, 2e-3 * std::max(f, g))
                        << "kind " << m.kind << " roughness " << m.roughness << " outside " << outside << " wo ("
                        << a[k][0] << ", " << a[k][1] << ", " << a[k][2] << ") wi (" << b[k][0] << ", " << b[k][1]
                        << ", " << b[k][2] << ")";
                }
            }
            EXPECT_GT(compared, 100) << "kind " << m.kind;
        }
    }
}

// The energy a white BSDF returns of light from wo: the integral of
// f |cos| over the sphere, refraction weighed by (n_i / n_o)^2 (the radiance
// factor is not energy).
double white_albedo(const device::MaterialRecord& m, double cos_o, bool outside)
{
    const Grid& grid = integration_grid();
    const std::vector<ProbeEval> values = probe().eval(m, outside, direction_at(cos_o), grid.directions);
    const double eta = outside ? 1.0 / m.ior : m.ior;  // n_o / n_i
    double sum = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double f = values[i].f_cos[0] * grid.solid_angles[i];
        sum += grid.directions[i][2] < 0 ? f / (eta * eta) : f;
    }
    return sum;
}

// The grid's error on an albedo integral, for lobes of roughness 0.3 and up
// (alpha >= 0.09; narrower lobes are left to the furnace renders).
constexpr double kAlbedoIntegration = 3e-3;

// A white rough metal returns what GGX single scattering predicts (the
// host's independent quadrature of pbr_albedo_reference.cpp): less than 1,
// the more the rougher (no energy compensation).
TEST(BsdfEnergy, WhiteMetalMatchesSingleScatteringGgx)
{
    for (float r : {0.3f, 0.6f, 1.0f})
        for (double c : {0.95, 0.6, 0.3}) {
            const double albedo = white_albedo(pbr({1, 1, 1}, r, 1), c, true);
            const double reference = pbr_specular_albedo(c, r, 256, 1.0);
            EXPECT_NEAR(albedo, reference, kAlbedoIntegration) << "roughness " << r << " cos " << c;
            EXPECT_LE(albedo, 1.0 + kAlbedoIntegration);
        }
}

// The largest amount by which kernels/bsdf_pbr_albedo.cl's table overstates
// the layer's albedo (its header says), the most a white pbr dielectric can lose.
double table_largest_raise() { return pbr_albedo_table().largest_raise; }

// A white dielectric-based pbr material: the specular layer plus the diffuse
// base it lets through return all the light, less the table's margin at most.
TEST(BsdfEnergy, WhitePlasticLosesAtMostTheTablesMarginAndNeverGains)
{
    const double margin = table_largest_raise();
    ASSERT_GT(margin, 0.0);
    ASSERT_LT(margin, 0.05);
    for (float r : {0.3f, 0.6f, 1.0f})
        for (double c : {0.95, 0.6, 0.3, 0.1}) {
            const double albedo = white_albedo(pbr({1, 1, 1}, r, 0), c, true);
            EXPECT_LE(albedo, 1.0 + kAlbedoIntegration) << "roughness " << r << " cos " << c;
            EXPECT_GE(albedo, 1.0 - margin - kAlbedoIntegration) << "roughness " << r << " cos " << c;
        }
}

// Smooth, the coat is a delta lobe of reflectance F(cos) = 0.04 + 0.96 (1 - cos)^5
// (outside bsdf_eval), and the base returns exactly the rest.
TEST(BsdfEnergy, SmoothPlasticBaseReturnsWhatTheCoatDoesNotReflect)
{
    for (double c : {0.95, 0.6, 0.3, 0.1}) {
        const double albedo = white_albedo(pbr({1, 1, 1}, 0, 0), c, true);
        EXPECT_NEAR(albedo, 1.0 - (0.04 + 0.96 * std::pow(1.0 - c, 5.0)), kAlbedoIntegration) << "cos " << c;
    }
}

// Rough glass returns what Walter et al.'s single-scattering model predicts
// (an independent quadrature on the host), from either side: at most what arrives.
TEST(BsdfEnergy, WhiteRoughGlassMatchesSingleScatteringAndNeverGains)
{
    for (float r : {0.3f, 0.6f, 1.0f})
        for (double c : {0.95, 0.6, 0.3})
            for (bool outside : {true, false}) {
                const double albedo = white_albedo(glass(r), c, outside);
                const double reference =
                    rough_dielectric_albedo(c, r, outside ? 1.0 : 1.5, outside ? 1.5 : 1.0, 256);
                EXPECT_NEAR(albedo, reference, kAlbedoIntegration)
                    << "roughness " << r << " cos " << c << " outside " << outside;
                EXPECT_LE(albedo, 1.0 + kAlbedoIntegration);
            }
}

}  // namespace
}  // namespace orb::render::test
