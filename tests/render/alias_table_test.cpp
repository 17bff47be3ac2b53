// The alias table picks each item with its probability: exact slot
// arithmetic, and a chi-squared test of many picks against the weights.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "alias_table.h"

using namespace orb::render;

namespace {

// The probability the table gives item i, from its slots (exact, no sampling).
std::vector<double> implied_probabilities(const AliasTable& t) {
    const double n = static_cast<double>(t.slots.size());
    std::vector<double> p(t.slots.size(), 0.0);
    for (std::size_t s = 0; s < t.slots.size(); ++s) {
        p[s] += t.slots[s].threshold / n;
        p[t.slots[s].alias] += (1.0 - t.slots[s].threshold) / n;
    }
    return p;
}

}  // namespace

TEST(AliasTable, SlotsImplyTheWeightsProbabilities) {
    std::mt19937 rng(7);
    std::exponential_distribution<double> weight(1.0);
    for (std::size_t n : {1u, 2u, 3u, 17u, 1000u}) {
        std::vector<double> w(n);
        for (double& x : w) x = weight(rng);
        w[0] = 0.0;  // an item that must never be picked
        if (n == 1) w[0] = 2.0;
        const AliasTable t = build_alias_table(w);
        double sum = 0;
        for (double x : w) sum += x;
        const auto p = implied_probabilities(t);
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_NEAR(p[i], w[i] / sum, 1e-6) << "n=" << n << " item " << i;
            EXPECT_NEAR(t.probability[i], w[i] / sum, 1e-7);
        }
    }
}

TEST(AliasTable, PicksFollowTheWeightsChiSquared) {
    const std::vector<double> w{1, 2, 3, 4, 10, 0.5, 0.25, 30};
    const AliasTable t = build_alias_table(w);
    const int draws = 400000;
    std::vector<int> count(w.size(), 0);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < draws; ++i) ++count[sample_alias_table(t, u(rng))];
    double sum = 0, chi2 = 0;
    for (double x : w) sum += x;
    for (std::size_t i = 0; i < w.size(); ++i) {
        const double expected = draws * w[i] / sum;
        chi2 += (count[i] - expected) * (count[i] - expected) / expected;
    }
    // 7 degrees of freedom: P(chi2 > 24.32) = 0.001.
    EXPECT_LT(chi2, 24.32);
}

TEST(AliasTable, RefusesWeightsThatMeanNothing) {
    EXPECT_THROW(build_alias_table(std::vector<double>{}), std::invalid_argument);
    EXPECT_THROW(build_alias_table(std::vector<double>{0, 0}), std::invalid_argument);
    EXPECT_THROW(build_alias_table(std::vector<double>{1, -1}), std::invalid_argument);
    EXPECT_THROW(build_alias_table(std::vector<double>{1, NAN}), std::invalid_argument);
}
