#include "environment_distribution.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace orb::render {
namespace {

// Cumulative sums of weights[0, n), normalised, as floats ending in exactly 1.
// A run whose weights are all 0 becomes uniform (it is never chosen, but its
// table must still be a valid distribution).
void append_cdf(const double* weights, std::size_t n, std::vector<float>& out) {
    double total = 0;
    for (std::size_t i = 0; i < n; ++i) total += weights[i];
    double running = 0;
    for (std::size_t i = 0; i < n; ++i) {
        running += total > 0 ? weights[i] : 1.0;
        const double share = running / (total > 0 ? total : double(n));
        // Rounding a non-decreasing sequence to float keeps it non-decreasing.
        out.push_back(i + 1 == n ? 1.0f : static_cast<float>(std::min(share, 1.0)));
    }
}

// Probability of entry k of a stored run: the float interval it owns.
double stored_share(const float* cdf, std::size_t k) {
    return static_cast<double>(cdf[k]) - (k == 0 ? 0.0 : static_cast<double>(cdf[k - 1]));
}

// First entry whose upper bound exceeds u: the same search as the kernel's.
std::size_t first_above(const float* cdf, std::size_t n, float u) {
    std::size_t lo = 0, hi = n - 1;
    while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (cdf[mid] > u)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

}  // namespace

double environment_texel_solid_angle(int row, int width, int height) {
    const double theta_top = std::numbers::pi * row / height;
    const double theta_bottom = std::numbers::pi * (row + 1) / height;
    // cos a - cos b = 2 sin((a + b) / 2) sin((b - a) / 2), exact near the poles too.
    const double band = 2.0 * std::sin(0.5 * (theta_top + theta_bottom)) * std::sin(0.5 * (theta_bottom - theta_top));
    return 2.0 * std::numbers::pi / width * band;
}

EnvironmentDistribution build_environment_distribution(const std::vector<double>& weights, int width, int height) {
    if (width < 1 || height < 1) throw std::invalid_argument("an environment distribution needs at least one texel");
    const std::size_t w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
    if (weights.size() != w * h) throw std::invalid_argument("one weight per texel is required");

    EnvironmentDistribution d;
    d.width = width;
    d.height = height;
    std::vector<double> texel_weight(w * h), row_weight(h, 0.0);
    for (std::size_t r = 0; r < h; ++r) {
        const double solid_angle = environment_texel_solid_angle(static_cast<int>(r), width, height);
        for (std::size_t c = 0; c < w; ++c) {
            const double weight = std::max(0.0, weights[r * w + c]) * solid_angle;
            texel_weight[r * w + c] = weight;
            row_weight[r] += weight;
        }
        d.total_weight += row_weight[r];
    }

    d.cdf.reserve(h + w * h);
    append_cdf(row_weight.data(), h, d.cdf);
    for (std::size_t r = 0; r < h; ++r) append_cdf(texel_weight.data() + r * w, w, d.cdf);

    d.probability.resize(w * h);
    d.pdf.resize(w * h);
    for (std::size_t r = 0; r < h; ++r) {
        const double row_share = stored_share(d.cdf.data(), r);
        const double solid_angle = environment_texel_solid_angle(static_cast<int>(r), width, height);
        const float* columns = d.cdf.data() + h + r * w;
        for (std::size_t c = 0; c < w; ++c) {
            const double p = d.total_weight > 0 ? row_share * stored_share(columns, c) : 0.0;
            d.probability[r * w + c] = p;
            d.pdf[r * w + c] = p / solid_angle;
        }
    }
    return d;
}

std::size_t sample_environment_texel(const EnvironmentDistribution& d, float u_row, float u_column) {
    const std::size_t w = static_cast<std::size_t>(d.width), h = static_cast<std::size_t>(d.height);
    const std::size_t row = first_above(d.cdf.data(), h, u_row);
    const std::size_t column = first_above(d.cdf.data() + h + row * w, w, u_column);
    return row * w + column;
}

}  // namespace orb::render
