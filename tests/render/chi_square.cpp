#include "chi_square.h"

#include <cmath>
#include <limits>

namespace orb::render::test {
namespace {

// Regularised lower incomplete gamma P(a, x) by its power series, for x < a + 1.
double gamma_p_series(double a, double x) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 100000; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::fabs(term) < std::fabs(sum) * 1e-15) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Regularised upper incomplete gamma Q(a, x) by Lentz's continued fraction, for x >= a + 1.
double gamma_q_fraction(double a, double x) {
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
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

}  // namespace

double chi_square_tail(double x, int k) {
    if (x <= 0) return 1.0;
    const double a = 0.5 * k, half = 0.5 * x;
    return half < a + 1.0 ? 1.0 - gamma_p_series(a, half) : gamma_q_fraction(a, half);
}

ChiSquareResult chi_square_test(const std::vector<double>& expected, const std::vector<double>& observed) {
    ChiSquareResult result;
    double pooled_expected = 0, pooled_observed = 0;
    int cells = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (expected[i] == 0) {
            if (observed[i] > 0)
                result.note += "cell " + std::to_string(i) + " expects nothing but received " +
                               std::to_string(observed[i]) + "; ";
            continue;
        }
        if (expected[i] < 5) {
            pooled_expected += expected[i];
            pooled_observed += observed[i];
            continue;
        }
        const double diff = observed[i] - expected[i];
        result.statistic += diff * diff / expected[i];
        ++cells;
    }
    if (pooled_expected > 0) {
        const double diff = pooled_observed - pooled_expected;
        result.statistic += diff * diff / pooled_expected;
        ++cells;
    }
    result.degrees_of_freedom = cells - 1;
    result.p_value = result.degrees_of_freedom > 0 ? chi_square_tail(result.statistic, result.degrees_of_freedom) : 1.0;
    return result;
}

}  // namespace orb::render::test
