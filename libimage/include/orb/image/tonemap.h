// One pass of a loaded image -> a display image: colour passes through an
// OCIO display/view (with exposure and looks), data passes (normals, depth,
// ids, variance) through their visual mappings.
#pragma once

#include <string>

#include "orb/image/color_config.h"
#include "orb/image/display_transform.h"
#include "orb/image/image.h"
#include "orb/image/passes.h"

namespace orb::image {

// `view` must be resolved (resolve_display_view) with the input's colour space.
// The result is display-encoded RGB, or RGBA (straight alpha) when the pass has alpha.
Image tonemap_pass(const Pass& pass, const ColorConfig& config, const DisplayView& view);

}  // namespace orb::image
