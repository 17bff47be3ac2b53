// Labelled pictures in one grid, for a quick look: every pass of a render,
// or one pass of many frames (or files).
#pragma once

#include <string>
#include <vector>

#include "orb/image/color_config.h"
#include "orb/image/display_transform.h"
#include "orb/image/image.h"

namespace orb::image {

// Colour passes go through `view` (resolved; exposure applies to light
// passes, not to albedo); normals, depth, ids and variance use the mappings of
// visual_mapping.h. Tiles are laid out in a near-square grid, each under a
// label with its pass name. Returns display-encoded RGB.
Image make_contact_sheet(const Image& all_channels, const ColorConfig& config, const DisplayView& view);

struct SheetTile {
    std::string label;
    Image picture;  // display-encoded RGB (further channels are not shown)
};

// The layout both sheets share: tiles of one size in a near-square grid
// (columns = ceil(sqrt(count)), filled row by row in the order given), each
// under its label, on a dark grey ground with a gap between cells. Throws
// orb::InputError when there are no tiles or they differ in size (naming them).
Image lay_out_sheet(const std::vector<SheetTile>& tiles);

// Where tile `index` of `count` tiles of size w x h lies in lay_out_sheet's
// result: its picture's top-left corner, and the sheet's size.
struct SheetGeometry {
    int columns = 0, rows = 0;
    int label_height = 0, gap = 0;
    int sheet_width = 0, sheet_height = 0;
    int picture_x(int index) const;
    int picture_y(int index) const;
    int tile_width = 0, tile_height = 0;
};
SheetGeometry sheet_geometry(int count, int tile_width, int tile_height);

// `image` made `factor` times smaller in each direction by averaging each
// factor x factor block of its (scene-linear, premultiplied) values; the
// last row and column of blocks average the pixels they have. factor 1 is a copy.
Image box_downscale(const Image& image, int factor);

// The same size, each block's top-left pixel: for data (ids, depths,
// normals), which averaging would turn into values no pixel has.
Image nearest_downscale(const Image& image, int factor);

}  // namespace orb::image
