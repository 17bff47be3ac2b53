// Readable pictures of non-colour passes, as display-encoded RGB in [0,1]:
//   normal:   0.5 + 0.5 n per axis (the usual normal-map colours)
//   depth:    near = white, far = black, over the finite, positive depth range;
//             no hit (infinite or zero depth) = black
//   id:       each id hashed to its own colour (0 stays black)
//   variance: standard deviation normalised by its 99th percentile
//   data:     each channel normalised over its finite range
#pragma once

#include "orb/image/image.h"
#include "orb/image/passes.h"

namespace orb::image {

Image visualize_data_pass(const Pass& pass);

}  // namespace orb::image
