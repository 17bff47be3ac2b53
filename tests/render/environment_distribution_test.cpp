// The environment's 2D distribution (librender/src/environment_distribution.h):
// texels are picked in proportion to radiance times solid angle, the density
// the kernels report is each texel's realised probability over its solid
// angle, and a chi-squared test of many picks against those probabilities.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "chi2.h"
#include "environment_distribution.h"

namespace orb::render::test {
namespace {

constexpr double kFourPi = 4.0 * std::numbers::pi;

// How far a texel's probability in the float tables may be from the exact
// one: each stored cumulative entry is within 2^-25 of its exact value, so a
// share (the difference of two entries) within 2^-24, and the texel's
// probability, row share times column share, within
// 2^-24 (p_row + p_column) + 2^-48 of row share times column share.
double float_table_error(double p_row, double p_column) {
    return std::ldexp(1.0, -24) * (p_row + p_column) + std::ldexp(1.0, -48);
}

// Weights with dark texels, a dark row, a bright texel and a smooth rest.
std::vector<double> test_weights(int width, int height, unsigned seed) {
    std::mt19937 rng(seed);
    std::exponential_distribution<double> radiance(1.0);
    std::vector<double> w(static_cast<std::size_t>(width) * height);
    for (double& x : w) x = radiance(rng);
    for (int c = 0; c < width; ++c) w[static_cast<std::size_t>(2 * width + c)] = 0.0;  // row 2 is black
    w[5] = 0.0;
    w[static_cast<std::size_t>(width * (height - 1) + 3)] = 0.0;
    w[static_cast<std::size_t>(width * (height / 2) + width / 3)] = 200.0;  // a sun
    return w;
}

TEST(EnvironmentDistribution, TexelSolidAnglesCoverTheSphere) {
    for (auto [width, height] : {std::pair{1, 1}, std::pair{4, 2}, std::pair{64, 32}, std::pair{7, 300}}) {
        double total = 0;
        for (int row = 0; row < height; ++row) total += width * environment_texel_solid_angle(row, width, height);
        EXPECT_NEAR(total, kFourPi, 1e-12) << width << "x" << height;
    }
    // A texel's solid angle is (2 pi / width) (cos theta_top - cos theta_bottom).
    const double expected = 2.0 * std::numbers::pi / 8 * (std::cos(std::numbers::pi * 3 / 16) - std::cos(std::numbers::pi * 4 / 16));
    EXPECT_NEAR(environment_texel_solid_angle(3, 8, 16), expected, 1e-15);
}

TEST(EnvironmentDistribution, AConstantMapIsUniformOverTheSphere) {
    for (auto [width, height] : {std::pair{1, 1}, std::pair{16, 8}, std::pair{3, 40}}) {
        const EnvironmentDistribution d =
            build_environment_distribution(std::vector<double>(std::size_t(width) * height, 2.5), width, height);
        for (int row = 0; row < height; ++row) {
            const double solid_angle = environment_texel_solid_angle(row, width, height);
            const double p_row = width * solid_angle / kFourPi, p_column = 1.0 / width;
            for (int c = 0; c < width; ++c)
                EXPECT_NEAR(d.pdf[std::size_t(row * width + c)], 1.0 / kFourPi,
                            float_table_error(p_row, p_column) / solid_angle)
                    << width << "x" << height << ", texel " << c << ", " << row;
        }
    }
}

TEST(EnvironmentDistribution, ProbabilitiesAreRadianceTimesSolidAngle) {
    const int width = 24, height = 12;
    const std::vector<double> w = test_weights(width, height, 3);
    const EnvironmentDistribution d = build_environment_distribution(w, width, height);
    double total = 0;
    for (int row = 0; row < height; ++row)
        for (int c = 0; c < width; ++c) total += w[std::size_t(row * width + c)] * environment_texel_solid_angle(row, width, height);
    EXPECT_NEAR(d.total_weight, total, 1e-12 * total);
    double sum = 0;
    for (int row = 0; row < height; ++row) {
        const double solid_angle = environment_texel_solid_angle(row, width, height);
        double row_weight = 0;
        for (int c = 0; c < width; ++c) row_weight += w[std::size_t(row * width + c)] * solid_angle;
        for (int c = 0; c < width; ++c) {
            const std::size_t i = std::size_t(row * width + c);
            const double intended = w[i] * solid_angle / total;
            const double p_column = row_weight > 0 ? w[i] * solid_angle / row_weight : 0.0;
            EXPECT_NEAR(d.probability[i], intended, float_table_error(row_weight / total, p_column))
                << "texel " << c << ", " << row;
            EXPECT_NEAR(d.pdf[i], d.probability[i] / solid_angle, 1e-12 * d.pdf[i]);
            if (w[i] == 0) {
                EXPECT_EQ(d.probability[i], 0.0);
            }
            sum += d.probability[i];
        }
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
}

TEST(EnvironmentDistribution, PicksFollowTheProbabilitiesChiSquared) {
    const int width = 24, height = 12;
    const EnvironmentDistribution d = build_environment_distribution(test_weights(width, height, 5), width, height);
    const int draws = 1'000'000;
    std::vector<double> observed(d.probability.size(), 0.0), expected(d.probability.size());
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int i = 0; i < draws; ++i) {
        const float u = uniform(rng), v = uniform(rng);
        observed[sample_environment_texel(d, u, v)] += 1;
    }
    for (std::size_t i = 0; i < expected.size(); ++i) expected[i] = d.probability[i] * draws;
    const Chi2Result result = pearson_chi2(observed, expected);
    EXPECT_TRUE(result.problem.empty()) << result.problem;  // black texels and the black row are never picked
    EXPECT_GT(result.dof, 200);
    // Significance 1%, as pbrt's and Mitsuba's sampler tests use.
    EXPECT_GT(result.p_value, 0.01) << "chi2 " << result.statistic << " with " << result.dof << " dof";
}

TEST(EnvironmentDistribution, TheChiSquaredTestNoticesAWrongDistribution) {
    // The same picks judged against the distribution without the sin(theta)
    // weighting must fail: the test has the power to see that mistake.
    const int width = 16, height = 8;
    const std::vector<double> w(std::size_t(width) * height, 1.0);
    const EnvironmentDistribution d = build_environment_distribution(w, width, height);
    const int draws = 200'000;
    std::vector<double> observed(w.size(), 0.0), unweighted(w.size(), double(draws) / double(w.size()));
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int i = 0; i < draws; ++i) {
        const float u = uniform(rng), v = uniform(rng);
        observed[sample_environment_texel(d, u, v)] += 1;
    }
    EXPECT_LT(pearson_chi2(observed, unweighted).p_value, 1e-6);
}

TEST(EnvironmentDistribution, ChiSquaredTailMatchesTables) {
    // Quantiles from standard tables: P(X > x) for k degrees of freedom.
    EXPECT_NEAR(chi2_survival(3.841, 1), 0.05, 1e-4);
    EXPECT_NEAR(chi2_survival(24.32, 7), 0.001, 1e-5);
    EXPECT_NEAR(chi2_survival(135.807, 100), 0.01, 1e-4);
    EXPECT_NEAR(chi2_survival(1.0, 10), 0.99983, 1e-5);
}

TEST(EnvironmentDistribution, UnresolvableSharesGetNoDensity) {
    // A texel whose share is below what a float next to 1 resolves is never
    // picked by the float tables, so it must not claim a density either
    // (multiple importance sampling then leaves it to BSDF sampling).
    const int width = 4, height = 1;
    const EnvironmentDistribution d = build_environment_distribution({1.0, 1e-12, 1e-12, 1.0}, width, height);
    for (std::size_t i = 0; i < d.probability.size(); ++i) {
        const float* columns = d.cdf.data() + height;
        const double stored = double(columns[i]) - (i == 0 ? 0.0 : double(columns[i - 1]));
        EXPECT_EQ(d.probability[i], stored) << "texel " << i;
    }
    EXPECT_EQ(d.probability[1], 0.0);
    EXPECT_EQ(d.pdf[1], 0.0);
}

TEST(EnvironmentDistribution, RefusesAnEmptyOrMismatchedMap) {
    EXPECT_THROW(build_environment_distribution({}, 0, 0), std::invalid_argument);
    EXPECT_THROW(build_environment_distribution({1, 2, 3}, 2, 2), std::invalid_argument);
}

}  // namespace
}  // namespace orb::render::test
