#include "orb/image/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "orb/scene/error.h"

namespace orb::image {
namespace {

// |t - r| where equal values (including equal infinities) count as no error
// and a NaN on either side as an infinite one.
double abs_difference(float r, float t) {
    if (r == t) return 0.0;
    if (std::isnan(r) || std::isnan(t)) return std::numeric_limits<double>::infinity();
    return std::fabs(static_cast<double>(t) - static_cast<double>(r));
}

bool differs(float r, float t, Tolerance tolerance) {
    const double difference = abs_difference(r, t);
    if (std::isinf(difference)) return true;  // else an infinite max(|r|, |t|) would excuse it
    const double larger = std::max(std::fabs(static_cast<double>(r)), std::fabs(static_cast<double>(t)));
    return difference > tolerance.absolute + tolerance.relative * larger;
}

void check_same_shape(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height || a.channels() != b.channels())
        throw InputError("internal: metrics need images of the same shape");
}

}  // namespace

ErrorStats compute_error_stats(const Image& reference, const Image& test) {
    check_same_shape(reference, test);
    ErrorStats s;
    const int n = reference.channels();
    const size_t count = reference.pixels.size();
    if (count == 0) return s;
    double sum_abs = 0, sum_sq = 0, sum_rel = 0;
    double max_abs = -1;
    size_t max_index = 0;
    double peak = 1.0;
    for (size_t i = 0; i < count; ++i) {
        const float r = reference.pixels[i];
        for (float v : {r, test.pixels[i]})
            if (std::isfinite(v) && v > peak) peak = v;
        const double d = abs_difference(r, test.pixels[i]);
        if (!std::isfinite(d)) ++s.nonfinite;
        sum_abs += d;
        sum_sq += d * d;
        const double rr = std::isfinite(r) ? static_cast<double>(r) : 0.0;
        sum_rel += d * d / (rr * rr + kRelMseEpsilon);
        if (d > max_abs) {
            max_abs = d;
            max_index = i;
        }
    }
    s.mean_abs_error = sum_abs / count;
    s.rmse = std::sqrt(sum_sq / count);
    s.relmse = sum_rel / count;
    s.psnr = s.rmse > 0 ? 20.0 * std::log10(peak / s.rmse) : std::numeric_limits<double>::infinity();
    s.max_abs_error = max_abs;
    const size_t pixel = max_index / n;
    s.max_x = static_cast<int>(pixel % reference.width);
    s.max_y = static_cast<int>(pixel / reference.width);
    s.max_channel = reference.channel_names[max_index % n];
    return s;
}

double percent_pixels_over(const Image& reference, const Image& test, Tolerance tolerance) {
    check_same_shape(reference, test);
    const int n = reference.channels();
    const size_t pixels = reference.pixel_count();
    if (pixels == 0) return 0.0;
    size_t over = 0;
    for (size_t p = 0; p < pixels; ++p) {
        for (int c = 0; c < n; ++c) {
            if (differs(reference.pixels[p * n + c], test.pixels[p * n + c], tolerance)) {
                ++over;
                break;
            }
        }
    }
    return 100.0 * static_cast<double>(over) / static_cast<double>(pixels);
}

}  // namespace orb::image
