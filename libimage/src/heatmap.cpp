#include "orb/image/heatmap.h"

#include <algorithm>
#include <cmath>

#include "orb/image/magma.h"

namespace orb::image {

Image magma_heatmap(const std::vector<float>& error, int width, int height) {
    Image out(width, height, {"R", "G", "B"});
    for (size_t i = 0; i < error.size() && i < out.pixel_count(); ++i) {
        const auto rgb = magma(error[i]);
        std::copy(rgb.begin(), rgb.end(), &out.pixels[i * 3]);
    }
    return out;
}

Image normalized_heatmap(const Image& reference, const Image& test) {
    const int n = reference.channels();
    std::vector<float> error(reference.pixel_count(), 0.0f);
    float largest = 0.0f;
    for (size_t p = 0; p < error.size(); ++p) {
        float e = 0.0f;
        for (int c = 0; c < n; ++c) {
            const float r = reference.pixels[p * n + c], t = test.pixels[p * n + c];
            const float d = r == t ? 0.0f : std::fabs(t - r);
            e = std::max(e, std::isnan(d) ? INFINITY : d);
        }
        error[p] = e;
        if (std::isfinite(e)) largest = std::max(largest, e);
    }
    for (float& e : error) e = largest > 0 ? (std::isfinite(e) ? e / largest : 1.0f) : 0.0f;
    return magma_heatmap(error, reference.width, reference.height);
}

}  // namespace orb::image
