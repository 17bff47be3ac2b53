// Error maps as pictures.
#pragma once

#include <vector>

#include "orb/image/image.h"

namespace orb::image {

// Per-pixel errors in [0,1] (FLIP) -> display-encoded RGB through magma.
Image magma_heatmap(const std::vector<float>& error, int width, int height);

// Per-pixel absolute errors of any scale -> magma, normalised by the largest
// finite error (for passes FLIP does not apply to).
Image normalized_heatmap(const Image& reference, const Image& test);

}  // namespace orb::image
