// Pixel error statistics between a reference image and a test image of the
// same size and channel count. All statistics run over every channel given
// (callers pass colour channels without alpha).
#pragma once

#include <string>

#include "orb/film/pixel_error.h"
#include "orb/image/image.h"

namespace orb::image {

struct ErrorStats {
    double mean_abs_error = 0;  // mean over pixels and channels of |t - r|
    double max_abs_error = 0;   // largest |t - r|
    int max_x = 0, max_y = 0;   // where it is
    std::string max_channel;    // and in which channel
    double rmse = 0;            // sqrt(mean (t - r)^2)
    double psnr = 0;            // 20 log10(peak / rmse), +inf if identical; peak = max(1, largest
                                // value in either image), exactly as OIIO's idiff reports it
    double relmse = 0;          // mean (t - r)^2 / (r^2 + 0.01), Rousselle et al. 2011
    size_t nonfinite = 0;       // values that are NaN/inf in one image and differ in the other
};

// The one definition, which adaptive sampling's error estimate shares (orb/film/pixel_error.h).
constexpr double kRelMseEpsilon = film::kRelMseEpsilon;

ErrorStats compute_error_stats(const Image& reference, const Image& test);

// When two values count as different: |t - r| > absolute + relative * max(|r|, |t|).
// A NaN against anything, or an infinity against a finite value, always does.
struct Tolerance {
    double absolute = 0;
    double relative = 0;
};

// Percentage of pixels where any channel differs by more than `tolerance`.
double percent_pixels_over(const Image& reference, const Image& test, Tolerance tolerance);
inline double percent_pixels_over(const Image& reference, const Image& test, double threshold) {
    return percent_pixels_over(reference, test, Tolerance{threshold, 0.0});
}

}  // namespace orb::image
