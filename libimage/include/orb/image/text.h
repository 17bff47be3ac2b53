// Labels on images: OpenImageIO's FreeType text where a font is installed,
// else a built-in 5x7 bitmap font, so labels never silently go missing.
#pragma once

#include <string>

#include "orb/image/image.h"

namespace orb::image {

// Draws `text` in white into an RGB(A) image; (x, y) is the top-left corner of
// a line `height` pixels tall. Characters outside the image are clipped.
void draw_label(Image& image, int x, int y, int height, const std::string& text);

// The built-in bitmap font alone (exposed for tests).
void draw_bitmap_label(Image& image, int x, int y, int height, const std::string& text);

}  // namespace orb::image
