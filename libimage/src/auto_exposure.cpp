#include "orb/image/auto_exposure.h"

#include <algorithm>
#include <cmath>

namespace orb::image {

AutoExposure auto_exposure(const Image& image, const std::array<double, 3>& luma) {
    const int n = image.channels();
    AutoExposure result;
    if (n < 3) return result;
    const bool has_alpha = n >= 4;
    double log_sum = 0.0;
    for (size_t p = 0; p < image.pixel_count(); ++p) {
        const float* px = &image.pixels[p * n];
        double y = luma[0] * px[0] + luma[1] * px[1] + luma[2] * px[2];
        if (has_alpha) {
            if (!(px[3] > 0.0f)) continue;
            y /= px[3];
        }
        if (!std::isfinite(y) || !(y > 0.0)) continue;
        log_sum += std::log(y);
        ++result.pixels;
    }
    if (result.pixels == 0) return result;
    const double mean_log = log_sum / static_cast<double>(result.pixels);
    result.log_average = std::exp(mean_log);
    result.stops = std::clamp((std::log(kMiddleGrey) - mean_log) / std::log(2.0), -100.0, 100.0);
    return result;
}

}  // namespace orb::image
