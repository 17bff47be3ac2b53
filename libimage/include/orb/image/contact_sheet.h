// One labelled picture of every pass in a render, for a quick look.
#pragma once

#include "orb/image/color_config.h"
#include "orb/image/display_transform.h"
#include "orb/image/image.h"

namespace orb::image {

// Colour passes go through `view` (resolved; exposure applies to light
// passes, not to albedo); normals, depth, ids and variance use the mappings of
// visual_mapping.h. Tiles are laid out in a near-square grid, each under a
// label with its pass name. Returns display-encoded RGB.
Image make_contact_sheet(const Image& all_channels, const ColorConfig& config, const DisplayView& view);

}  // namespace orb::image
