// --auto-exposure: the exposure that maps an image's log-average luminance
// to middle grey, the "key" of Reinhard, Stark, Shirley and Ferwerda,
// "Photographic Tone Reproduction for Digital Images" (SIGGRAPH 2002), eq. 1
// with their key value a = 0.18 (eq. 2), the statistic OpenCV's
// TonemapReinhard and pfstmo's reinhard02 scale by.
#pragma once

#include <array>
#include <cstddef>

#include "orb/image/image.h"

namespace orb::image {

inline constexpr double kMiddleGrey = 0.18;

struct AutoExposure {
    double stops = 0.0;        // log2(0.18 / log_average), clamped to [-100, 100]; 0 when no pixel counts
    double log_average = 0.0;  // exp(mean of ln Y) over the pixels that count; 0 when none does
    std::size_t pixels = 0;    // how many pixels counted
};

// Over the first three channels of `image` (scene-linear, as the view will
// take them; with a fourth channel, alpha, colour is premultiplied and is
// divided by it, pixels of alpha 0 not counting), Y = luma . RGB. Pixels
// whose Y is not a finite number > 0 do not count: black (an empty sky with
// no environment) carries no exposure, and one would send the log-average
// to 0. An image with no pixel that counts (all black) gets 0 stops.
AutoExposure auto_exposure(const Image& image, const std::array<double, 3>& luma);

}  // namespace orb::image
