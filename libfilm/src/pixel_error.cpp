#include "orb/film/pixel_error.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace orb::film {

double pixel_samples(const Film& film, std::size_t pixel)
{
    if (!film.sample_count.empty()) return film.sample_count[pixel];
    return static_cast<double>(film.samples_per_pixel);
}

double pixel_relmse(const Film& film, std::size_t pixel)
{
    const double n = pixel_samples(film, pixel);
    if (n < 2) return std::numeric_limits<double>::infinity();
    double sum = 0;
    for (std::size_t c = 0; c < 3; ++c) {
        const double mean = film.radiance[pixel * 3 + c] / n;
        const double mean_sq = film.radiance_sq[pixel * 3 + c] / n;
        const double variance_of_mean = std::max(0.0, mean_sq - mean * mean) / (n - 1.0);
        sum += variance_of_mean / (mean * mean + kRelMseEpsilon);
    }
    return sum / 3.0;
}

std::vector<double> pixel_relmse(const Film& film)
{
    const std::size_t pixels = film.pixel_count();
    if (film.radiance.size() != pixels * 3 || film.radiance_sq.size() != pixels * 3)
        throw std::invalid_argument("estimating a film's error needs its radiance and radiance_sq channels");
    if (!film.sample_count.empty() && film.sample_count.size() != pixels)
        throw std::invalid_argument("the film's sample_count channel has the wrong size");
    std::vector<double> errors(pixels);
    for (std::size_t i = 0; i < pixels; ++i) errors[i] = pixel_relmse(film, i);
    return errors;
}

double frame_relmse(const std::vector<double>& pixel_errors)
{
    if (pixel_errors.empty()) return 0;
    double sum = 0;
    for (double e : pixel_errors) sum += e;
    return sum / static_cast<double>(pixel_errors.size());
}

}  // namespace orb::film
