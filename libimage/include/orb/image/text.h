// Labels on images: OpenImageIO's FreeType text where a font is installed,
// else a built-in 5x7 bitmap font, so labels never silently go missing.
#pragma once

#include <array>
#include <string>

#include "orb/image/image.h"

namespace orb::image {

// Draws `text` in `color` (white by default) into an RGB(A) image; (x, y) is
// the top-left corner of a line `height` pixels tall. Characters outside the
// image are clipped.
void draw_label(Image& image, int x, int y, int height, const std::string& text,
                const std::array<float, 3>& color = {1.0f, 1.0f, 1.0f});

// How many pixels wide draw_label draws `text` in a line `height` pixels tall.
int label_width(int height, const std::string& text);

// The built-in bitmap font alone (exposed for tests).
void draw_bitmap_label(Image& image, int x, int y, int height, const std::string& text,
                       const std::array<float, 3>& color = {1.0f, 1.0f, 1.0f});

}  // namespace orb::image
