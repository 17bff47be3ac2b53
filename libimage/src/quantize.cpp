#include "orb/image/quantize.h"
#include "orb/image/hash.h"

#include <algorithm>
#include <cmath>

namespace orb::image {
namespace {

float clamp01(float v) { return std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f); }

}  // namespace

std::vector<uint8_t> quantize_8bit_dithered(const Image& image) {
    std::vector<uint8_t> out(image.pixels.size());
    const int n = image.channels();
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < n; ++c) {
                const size_t i = image.index(x, y, c);
                const uint32_t h = hash32(static_cast<uint32_t>(x) * 0x9e3779b9U ^ hash32(static_cast<uint32_t>(y) * 0x85ebca6bU + c));
                const float u = static_cast<float>(h >> 8) * (1.0f / 16777216.0f);  // [0,1)
                const float code = std::floor(clamp01(image.pixels[i]) * 255.0f + u);
                out[i] = static_cast<uint8_t>(std::clamp(code, 0.0f, 255.0f));
            }
        }
    }
    return out;
}

std::vector<uint8_t> quantize_8bit(const Image& image) {
    std::vector<uint8_t> out(image.pixels.size());
    for (size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<uint8_t>(std::lround(clamp01(image.pixels[i]) * 255.0f));
    return out;
}

std::vector<uint16_t> quantize_16bit(const Image& image) {
    std::vector<uint16_t> out(image.pixels.size());
    for (size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<uint16_t>(std::lround(clamp01(image.pixels[i]) * 65535.0f));
    return out;
}

}  // namespace orb::image
