// FLIP, NVIDIA's perceptual difference evaluator, implemented from the papers:
//   LDR-FLIP: Andersson et al., "FLIP: A Difference Evaluator for Alternating
//             Images", Proc. ACM Comput. Graph. Interact. Tech. 3(2), 2020.
//   HDR-FLIP: Andersson et al., "Visualizing Errors in Rendered High Dynamic
//             Range Images", Eurographics 2021 short papers.
// The result is a per-pixel error in [0,1]; its mean is the usual summary.
#pragma once

#include <vector>

#include "orb/image/image.h"

namespace orb::image {

// Pixels per degree of visual angle for a 0.7 m wide 3840-pixel monitor seen
// from 0.7 m: FLIP's default observer (about 67.02).
double default_flip_ppd();

struct FlipResult {
    std::vector<float> error;  // width * height, each in [0,1]
    double mean = 0;
    double max = 0;
    bool hdr = false;
    // HDR-FLIP only: the exposure range (in stops) and number of exposures used.
    double start_exposure = 0, stop_exposure = 0;
    int exposures = 0;
};

// LDR-FLIP on display images whose first three channels are sRGB-encoded
// values (clamped to [0,1]).
FlipResult flip_ldr(const Image& reference, const Image& test, double ppd);

// HDR-FLIP on scene-linear Rec.709 images (first three channels; negatives
// are clamped to zero), with the ACES filmic tone mapper of the HDR-FLIP
// paper and the exposure range derived from the reference's luminance.
FlipResult flip_hdr(const Image& reference, const Image& test, double ppd);

}  // namespace orb::image
