// The legend of --color-by: a colour bar with the property's name and values
// for a numeric property, a swatch per category with its label for a
// categorical one (docs/orb-import.md, "Legend"). The colours are the
// display values the particles' colours come from (orb::ColorLegend), so the
// legend shows the map itself, not the map as lit in a render.
#pragma once

#include <string>
#include <vector>

#include "orb/image/image.h"
#include "orb/import/sphere_styling.h"

namespace orb::image {

enum class LegendOrientation {
    Vertical,    // a bar upright, the largest value at the top; categories in columns
    Horizontal,  // a bar lying down, the smallest value at the left; categories in rows
};

// Pixels [x0, x1) x [y0, y1).
struct PixelBox {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct LegendImage {
    Image image;  // display-encoded RGB, dark text on white
    // A numeric property: the bar. Its first and last row (vertical) or
    // column (horizontal) are the map's two ends exactly; between them the
    // map's position grows linearly, one step per pixel.
    PixelBox bar;
    std::vector<PixelBox> swatches;  // a categorical property: one per category, in the legend's order
};

LegendImage draw_legend(const ColorLegend& legend, LegendOrientation orientation);

// The map's position (0: range.first, 1: range.second) of the bar's pixel at
// (x, y), which must be inside legend.bar.
double bar_position(const LegendImage& legend, LegendOrientation orientation, int x, int y);

// The legend as a PNG file's bytes (8 bits, not dithered: flat colours).
std::string encode_legend_png(const ColorLegend& legend, LegendOrientation orientation);

}  // namespace orb::image
