#include "orb/image/visual_mapping.h"
#include "orb/image/hash.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace orb::image {
namespace {

Image normals(const Image& in) {
    Image out(in.width, in.height, {"R", "G", "B"});
    for (size_t p = 0; p < in.pixel_count(); ++p)
        for (int c = 0; c < 3; ++c) {
            const float v = in.pixels[p * 3 + c];
            out.pixels[p * 3 + c] = std::isfinite(v) ? std::clamp(0.5f + 0.5f * v, 0.0f, 1.0f) : 0.0f;
        }
    return out;
}

bool is_hit_depth(float z) { return std::isfinite(z) && z > 0.0f && z < 1e30f; }

Image depth(const Image& in) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (float z : in.pixels)
        if (is_hit_depth(z)) {
            lo = std::min(lo, z);
            hi = std::max(hi, z);
        }
    Image out(in.width, in.height, {"R", "G", "B"});
    for (size_t p = 0; p < in.pixel_count(); ++p) {
        const float z = in.pixels[p];
        float v = 0.0f;
        if (is_hit_depth(z)) v = hi > lo ? 1.0f - 0.9f * (z - lo) / (hi - lo) : 1.0f;  // far hits stay visible
        for (int c = 0; c < 3; ++c) out.pixels[p * 3 + c] = v;
    }
    return out;
}

Image ids(const Image& in) {
    Image out(in.width, in.height, {"R", "G", "B"});
    for (size_t p = 0; p < in.pixel_count(); ++p) {
        const float v = in.pixels[p];
        if (!std::isfinite(v) || v == 0.0f) continue;
        const uint32_t h = hash32(static_cast<uint32_t>(static_cast<int64_t>(v)) * 2654435761U + 1U);
        // Bright, distinct colours: each component in [0.25, 1].
        for (int c = 0; c < 3; ++c) out.pixels[p * 3 + c] = 0.25f + 0.75f * static_cast<float>((h >> (8 * c)) & 0xff) / 255.0f;
    }
    return out;
}

Image normalized_channels(const Image& in, bool standard_deviation) {
    const int n = in.channels();
    Image out(in.width, in.height, {"R", "G", "B"});
    std::vector<float> values;
    values.reserve(in.pixels.size());
    for (float v : in.pixels) {
        const float s = standard_deviation ? std::sqrt(std::max(v, 0.0f)) : v;
        if (std::isfinite(s)) values.push_back(s);
    }
    if (values.empty()) return out;
    float lo = *std::min_element(values.begin(), values.end());
    float hi;
    if (standard_deviation) {
        lo = 0.0f;
        const size_t k = std::min(values.size() - 1, values.size() * 99 / 100);
        std::nth_element(values.begin(), values.begin() + k, values.end());
        hi = values[k];
    } else {
        hi = *std::max_element(values.begin(), values.end());
    }
    const float range = hi > lo ? hi - lo : 1.0f;
    for (size_t p = 0; p < in.pixel_count(); ++p)
        for (int c = 0; c < 3; ++c) {
            float v = in.pixels[p * n + std::min(c, n - 1)];
            if (standard_deviation) v = std::sqrt(std::max(v, 0.0f));
            out.pixels[p * 3 + c] = std::isfinite(v) ? std::clamp((v - lo) / range, 0.0f, 1.0f) : 1.0f;
        }
    return out;
}

}  // namespace

Image visualize_data_pass(const Pass& pass) {
    switch (pass.kind) {
        case PassKind::Normal: return normals(pass.image);
        case PassKind::Depth: return depth(pass.image);
        case PassKind::Id: return ids(pass.image);
        case PassKind::Variance: return normalized_channels(pass.image, true);
        case PassKind::Data:
        case PassKind::Color: return normalized_channels(pass.image, false);
    }
    return normalized_channels(pass.image, false);
}

}  // namespace orb::image
