#include "orb/film/pixel_error.h"

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <vector>

#include "orb/film/parallel_blocks.h"

namespace orb::film {

double pixel_samples(const Film& film, std::size_t pixel)
{
    if (!film.sample_count.empty()) return static_cast<double>(film.sample_count[pixel]);
    return static_cast<double>(film.samples_per_pixel);
}

namespace {

// Var[mean] of each channel of pixel i, and its mean; false with fewer than two samples.
bool pixel_moments(const Film& film, std::size_t pixel, double mean[3], double variance_of_mean[3])
{
    const double n = pixel_samples(film, pixel);
    if (n < 2) return false;
    for (std::size_t c = 0; c < 3; ++c) {
        // As the device's decision computes them (kernels/adaptive.cl, fixed_sum_value).
        mean[c] = sum_value(Units::Fixed, film.radiance[pixel * 3 + c]) / n;
        const double mean_sq = sum_value(Units::Fixed, film.radiance_sq[pixel * 3 + c]) / n;
        variance_of_mean[c] = std::max(0.0, mean_sq - mean[c] * mean[c]) / (n - 1.0);
    }
    return true;
}

// A^2 in the denominator from the mean B: E[B^2] = A^2 + Var[B], so
// B^2 - Var[B] (at least 0). B^2 itself would let a pixel whose few
// samples include one very bright one (a firefly) pass for converged: its
// large variance and its large mean would cancel.
double relmse_of(const double mean[3], const double variance_of_mean[3])
{
    double sum = 0;
    for (int c = 0; c < 3; ++c) {
        const double converged_sq = std::max(0.0, mean[c] * mean[c] - variance_of_mean[c]);
        sum += variance_of_mean[c] / (converged_sq + kRelMseEpsilon);
    }
    return sum / 3.0;
}

void check_channels(const Film& film)
{
    const std::size_t pixels = film.pixel_count();
    if (film.radiance.size() != pixels * 3 || film.radiance_sq.size() != pixels * 3)
        throw std::invalid_argument("estimating a film's error needs its radiance and radiance_sq channels");
    if (!film.sample_count.empty() && film.sample_count.size() != pixels)
        throw std::invalid_argument("the film's sample_count channel has the wrong size");
}

}  // namespace

static_assert(info(Channel::radiance).units == Units::Fixed && info(Channel::radiance_sq).units == Units::Fixed,
              "the error estimate and kernels/adaptive.cl read radiance and radiance_sq as Fixed sums");

double pixel_relmse(const Film& film, std::size_t pixel)
{
    double mean[3], variance[3];
    if (!pixel_moments(film, pixel, mean, variance)) return std::numeric_limits<double>::infinity();
    return relmse_of(mean, variance);
}

std::vector<double> pixel_relmse(const Film& film)
{
    check_channels(film);
    const std::size_t pixels = film.pixel_count();
    std::vector<double> errors(pixels);
    // Every pixel on its own, so the cores share the image in blocks.
    for_each_block(pixels, [&](std::size_t, std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i) errors[i] = pixel_relmse(film, i);
    });
    return errors;
}

namespace {

constexpr std::size_t kGroup = ORB_DECISION_GROUP;

// values[0] = the sum of the group's values, added as the device's
// sum_pairwise adds them (kernels/adaptive.cl).
double sum_pairwise(std::array<double, kGroup>& values)
{
    for (std::size_t half = kGroup / 2; half > 0; half >>= 1)
        for (std::size_t l = 0; l < half; ++l) values[l] += values[l + half];
    return values[0];
}

}  // namespace

double frame_relmse(const std::vector<double>& pixel_errors)
{
    if (pixel_errors.empty()) return 0;
    const std::size_t groups = (pixel_errors.size() + kGroup - 1) / kGroup;
    std::vector<double> group_sums(groups);
    for_each_block(groups, [&](std::size_t, std::size_t first, std::size_t end) {
        std::array<double, kGroup> values;
        for (std::size_t g = first; g < end; ++g) {
            for (std::size_t l = 0; l < kGroup; ++l) {
                const std::size_t i = g * kGroup + l;
                values[l] = i < pixel_errors.size() ? pixel_errors[i] : 0.0;  // past the image: adds nothing
            }
            group_sums[g] = sum_pairwise(values);
        }
    });
    std::array<double, kGroup> running{};
    for (std::size_t l = 0; l < kGroup; ++l)
        for (std::size_t g = l; g < groups; g += kGroup) running[l] += group_sums[g];
    return sum_pairwise(running) / static_cast<double>(pixel_errors.size());
}

}  // namespace orb::film
