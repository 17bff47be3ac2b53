// The checks both ways of denoising an image make on its layers (an EXR read
// back, libdenoise/src/denoise_exr.cpp, or one being encoded,
// libdenoise/src/denoise_film.cpp), so both refuse the same inputs with the
// same words.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <atomic>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>

#include "orb/film/parallel_blocks.h"
#include "orb/tables/film_channels.h"

namespace orb::denoise::detail {

using Names = std::array<const char*, 3>;

// The three shown channels of a film channel's layer, and of the denoised
// layer, from the table.
Names names_of(film::Channel channel);
Names denoised_names();

// Throws orb::InputError naming `source` when the beauty, albedo or normal
// layer is missing (has(name): whether the image holds the channel).
void require_layers(const std::function<bool(const char*)>& has, const std::string& source);

// Throws orb::InputError when `value`, pixel `i` of `channel` of `layer`,
// is not finite (the filter spreads a NaN or an infinity over its whole
// neighbourhood).
void require_finite(float value, std::size_t i, int width, const std::string& channel, const char* layer,
                    const std::string& source);

// Writes a layer's three channels interleaved into `out` (pixels * 3
// floats) on every core of the host, value(c, i) being channel c of pixel i
// (a 1920x1080 layer is 6 million values: milliseconds on one core, which a
// GPU's filter takes for the whole image). A value that is not finite
// throws require_finite's error for the first such pixel, as one core would.
template <class Value>
void interleave_into(float* out, std::size_t pixels, int width, const Names& names, const char* layer,
                     const std::string& source, const Value& value) {
    constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
    std::atomic<std::size_t> first_bad{kNone};
    film::for_each_block(pixels, [&](std::size_t, std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i)
            for (int c = 0; c < 3; ++c) {
                const float v = value(c, i);
                out[3 * i + static_cast<std::size_t>(c)] = v;
                if (!std::isfinite(v)) {
                    std::size_t seen = first_bad.load();
                    // Channel by channel, as the layers are checked elsewhere.
                    const std::size_t at = static_cast<std::size_t>(c) * pixels + i;
                    while (at < seen && !first_bad.compare_exchange_weak(seen, at)) {
                    }
                }
            }
    });
    const std::size_t bad = first_bad.load();
    if (bad != kNone)
        require_finite(out[3 * (bad % pixels) + bad / pixels], bad % pixels, width, names[bad / pixels], layer, source);
}

}  // namespace orb::denoise::detail
