// Pearson's chi-square goodness-of-fit test, as the BSDF sampling tests of
// pbrt and Mitsuba use it: observed counts per bin against the counts a
// density predicts, bins expecting fewer than 5 pooled into one.
#pragma once

#include <string>
#include <vector>

namespace orb::render::test {

// P(X >= x) for X chi-square distributed with `dof` degrees of freedom
// (the regularised upper incomplete gamma function Q(dof / 2, x / 2)).
double chi2_survival(double x, int dof);

struct Chi2Result {
    double statistic = 0;
    int dof = 0;
    double p_value = 1;
    std::string problem;  // non-empty: samples fell where the density is zero
};

Chi2Result pearson_chi2(const std::vector<double>& observed, const std::vector<double>& expected,
                        double min_expected = 5.0);

// The significance level per test that keeps the chance of any false alarm
// among `tests` independent tests at `overall` (Sidak's correction).
double sidak_level(double overall, int tests);

}  // namespace orb::render::test
