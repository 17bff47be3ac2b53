#include <gtest/gtest.h>

#include "orb/image/text.h"

using namespace orb::image;

namespace {
int lit_pixels(const Image& img) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) n += img.at(x, y, 0) > 0.5f;
    return n;
}
}  // namespace

TEST(Text, BitmapFontDrawsEveryGlyphInsideItsBox) {
    Image img(200, 20, {"R", "G", "B"}, 0.0f);
    draw_bitmap_label(img, 2, 0, 18, "depth 0-9");
    EXPECT_GT(lit_pixels(img), 50);
    // Nothing beyond the text's advance (9 glyphs of 6 columns at scale 2).
    for (int y = 0; y < img.height; ++y)
        for (int x = 2 + 9 * 12; x < img.width; ++x) EXPECT_EQ(img.at(x, y, 0), 0.0f);
}

TEST(Text, LabelsAreDrawnWithOrWithoutFonts) {
    Image img(120, 24, {"R", "G", "B"}, 0.0f);
    draw_label(img, 0, 0, 24, "beauty");
    EXPECT_GT(lit_pixels(img), 20);
}

TEST(Text, ClipsAtTheImageEdge) {
    Image img(10, 5, {"R", "G", "B"}, 0.0f);
    draw_bitmap_label(img, -3, -2, 9, "WWWW");  // must not write out of bounds
    EXPECT_GT(lit_pixels(img), 0);
}
