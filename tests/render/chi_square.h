// Pearson's chi-squared test of observed counts against expected ones, as
// pbrt and Mitsuba test their samplers: cells expected to receive fewer than
// five samples are pooled into one, and the statistic's p-value comes from
// the chi-squared distribution (the regularised upper incomplete gamma
// function).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace orb::render::test {

struct ChiSquareResult {
    double statistic = 0;
    int degrees_of_freedom = 0;
    double p_value = 1;
    std::string note;  // problems that fail the test outright (samples where none can land)
};

// `expected`: the expected count per cell (the probabilities times the
// number of samples); `observed`: the counts. A cell expected to be empty
// must stay empty.
ChiSquareResult chi_square_test(const std::vector<double>& expected, const std::vector<double>& observed);

// P(X > x) for X chi-squared with k degrees of freedom.
double chi_square_tail(double x, int k);

}  // namespace orb::render::test
