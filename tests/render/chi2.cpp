#include "chi2.h"

#include <cmath>
#include <limits>

namespace orb::render::test {
namespace {

// Q(a, x) by the continued fraction (modified Lentz), for x >= a + 1.
double gamma_q_fraction(double a, double x)
{
    const double tiny = std::numeric_limits<double>::min() / std::numeric_limits<double>::epsilon();
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

// P(a, x) by its series, for x < a + 1.
double gamma_p_series(double a, double x)
{
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 10000; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::fabs(term) < std::fabs(sum) * 1e-16) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

}  // namespace

double chi2_survival(double x, int dof)
{
    if (x <= 0.0) return 1.0;
    const double a = 0.5 * dof, half = 0.5 * x;
    return half < a + 1.0 ? 1.0 - gamma_p_series(a, half) : gamma_q_fraction(a, half);
}

Chi2Result pearson_chi2(const std::vector<double>& observed, const std::vector<double>& expected, double min_expected)
{
    Chi2Result result;
    std::vector<double> obs, exp;
    double pooled_observed = 0, pooled_expected = 0;
    for (std::size_t k = 0; k < observed.size(); ++k) {
        if (expected[k] <= 0.0 && observed[k] > 0.0) {
            result.problem = "bin " + std::to_string(k) + " has " + std::to_string(observed[k]) +
                             " samples where the density is zero";
            return result;
        }
        if (expected[k] < min_expected) {
            pooled_observed += observed[k];
            pooled_expected += expected[k];
        } else {
            obs.push_back(observed[k]);
            exp.push_back(expected[k]);
        }
    }
    if (pooled_expected >= min_expected || obs.empty()) {
        obs.push_back(pooled_observed);
        exp.push_back(pooled_expected);
    } else {
        // Too little for a bin of its own: join the regular bin that expects least.
        std::size_t smallest = 0;
        for (std::size_t k = 1; k < exp.size(); ++k)
            if (exp[k] < exp[smallest]) smallest = k;
        obs[smallest] += pooled_observed;
        exp[smallest] += pooled_expected;
    }
    for (std::size_t k = 0; k < obs.size(); ++k) {
        if (exp[k] <= 0.0) continue;
        const double d = obs[k] - exp[k];
        result.statistic += d * d / exp[k];
    }
    result.dof = static_cast<int>(obs.size()) - 1;
    result.p_value = result.dof > 0 ? chi2_survival(result.statistic, result.dof) : 1.0;
    return result;
}

double sidak_level(double overall, int tests) { return 1.0 - std::pow(1.0 - overall, 1.0 / tests); }

}  // namespace orb::render::test
