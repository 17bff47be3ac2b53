// The pbr material's albedo table (kernels/bsdf_pbr_albedo.cl) against the
// host's independent quadrature: its interpolation never understates the
// layer's albedo E (or a white material would gain energy through its
// diffuse base) and stays close to it; each row's average is the cosine-
// weighted integral of the interpolation.
#include <gtest/gtest.h>

#include <cmath>

#include "pbr_albedo_reference.h"
#include "pbr_albedo_table.h"

namespace orb::render::test {
namespace {

TEST(PbrAlbedoTable, InterpolationBoundsTheLayerAlbedoFromAbove)
{
    const PbrAlbedoTable& t = pbr_albedo_table();
    ASSERT_EQ(t.size, kPbrAlbedoSize);
    EXPECT_NEAR(t.min_roughness, std::sqrt(1e-3), 1e-7);
    // Points off the nodes, spread over the table (a fixed low-discrepancy set).
    constexpr double kQuadratureError = 2e-4;  // of 96^2 samples against 1024^2
    double worst_excess = 0;
    for (int k = 0; k < 300; ++k) {
        const double cos_o = std::fmod(0.5 + k * 0.6180339887498949, 1.0);
        const double u = std::fmod(0.5 + k * 0.7548776662466927, 1.0);
        const double roughness = t.min_roughness + (1 - t.min_roughness) * u * u;  // denser at low roughness
        const double exact = pbr_specular_albedo(cos_o, roughness, 96);
        const double table = t.interpolate(cos_o, roughness);
        EXPECT_GE(table, exact - kQuadratureError) << "cos " << cos_o << " roughness " << roughness;
        worst_excess = std::max(worst_excess, table - exact);
    }
    EXPECT_LE(worst_excess, 0.1) << "the table should stay close to E";
}

TEST(PbrAlbedoTable, AveragesIntegrateTheInterpolation)
{
    const PbrAlbedoTable& t = pbr_albedo_table();
    for (int j = 0; j < t.size; ++j) {
        const double roughness = t.min_roughness + (1 - t.min_roughness) * j / (t.size - 1);
        double sum = 0;
        constexpr int kSteps = 4096;
        for (int i = 0; i < kSteps; ++i) {
            const double mu = (i + 0.5) / kSteps;
            sum += 2 * mu * t.interpolate(mu, roughness) / kSteps;
        }
        EXPECT_NEAR(t.average[static_cast<std::size_t>(j)], sum, 2e-6) << "row " << j;
    }
}

}  // namespace
}  // namespace orb::render::test
