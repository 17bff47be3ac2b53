// orb-tonemap --contact-sheet of frames: one pass of each frame (or input)
// in one labelled grid.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "test_support.h"

using namespace orb::image;
using namespace orb::image::test;

namespace {

const std::string kTonemap = quote(tonemap_exe());

// Frame f is a uniform grey of f / 8 (exact in 16 bits through the Raw view).
float grey_of(int frame) { return static_cast<float>(frame) / 8.0f; }

class TonemapSheet : public ::testing::Test {
protected:
    ScratchDir dir;
    void write_frames(int count, int width, int height) {
        for (int f = 1; f <= count; ++f) {
            char name[32];
            std::snprintf(name, sizeof name, "beauty.%04d.exr", f);
            write_exr(dir.path(name), Image(width, height, {"R", "G", "B"}, grey_of(f)));
        }
    }
};

// The layout the docs give: tiles of w x h in ceil(sqrt(n)) columns, a label
// of clamp(h / 12, 14, 40) pixels above each, gaps of max(4, label / 3).
struct Layout {
    int columns, label, gap;
    int x(int i, int w) const { return gap + (i % columns) * (w + gap); }
    int y(int i, int h) const { return gap + (i / columns) * (h + label + gap) + label; }
};

}  // namespace

TEST_F(TonemapSheet, FramesFillAGridInOrderUnderTheirNumbers) {
    write_frames(3, 8, 6);
    const auto r = run(kTonemap + " " + quote(dir.path("beauty.%04d.exr")) +
                       " --frames 1-3 --contact-sheet --view Raw --bits 16 -o " + quote(dir.path("sheet.png")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image sheet = read_image(dir.path("sheet.png"));
    const Layout layout{2, 14, 4};
    EXPECT_EQ(sheet.width, 2 * (8 + 4) + 4);
    EXPECT_EQ(sheet.height, 2 * (6 + 14 + 4) + 4);
    for (int i = 0; i < 3; ++i)
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 8; ++x)
                ASSERT_NEAR(sheet.at(layout.x(i, 8) + x, layout.y(i, 6) + y, 1), grey_of(i + 1), 1e-4)
                    << "frame " << i + 1 << " at " << x << "," << y;
    // The fourth cell is empty ground.
    EXPECT_NEAR(sheet.at(layout.x(3, 8) + 4, layout.y(3, 6) + 3, 0), 0.12, 1e-4);
}

TEST_F(TonemapSheet, AStepPicksFramesAndLargeFramesShrinkToThumbnails) {
    write_frames(5, 1000, 10);
    const auto r = run(kTonemap + " " + quote(dir.path("beauty.####.exr")) +
                       " --frames 1-5x4 --contact-sheet --view Raw --bits 16 -o " + quote(dir.path("sheet.png")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image sheet = read_image(dir.path("sheet.png"));
    // Frames 1 and 5, shrunk by 3 (to at most 480 wide): 334 x 4 tiles side by side.
    const Layout layout{2, 14, 4};
    EXPECT_EQ(sheet.width, 2 * (334 + 4) + 4);
    EXPECT_EQ(sheet.height, 4 + 14 + 4 + 4);
    EXPECT_NEAR(sheet.at(layout.x(0, 334) + 333, layout.y(0, 4) + 3, 0), grey_of(1), 1e-4);
    EXPECT_NEAR(sheet.at(layout.x(1, 334), layout.y(1, 4), 0), grey_of(5), 1e-4);
}

TEST_F(TonemapSheet, SeveralInputsMakeOneSheetWhenTheOutputIsAFile) {
    write_frames(2, 8, 6);
    const auto r = run(kTonemap + " " + quote(dir.path("beauty.0002.exr")) + " " + quote(dir.path("beauty.0001.exr")) +
                       " --contact-sheet --view Raw --bits 16 -o " + quote(dir.path("pair.png")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image sheet = read_image(dir.path("pair.png"));
    const Layout layout{2, 14, 4};
    EXPECT_NEAR(sheet.at(layout.x(0, 8), layout.y(0, 6), 0), grey_of(2), 1e-4);  // in the order given
    EXPECT_NEAR(sheet.at(layout.x(1, 8), layout.y(1, 6), 0), grey_of(1), 1e-4);
}

TEST_F(TonemapSheet, AMissingFrameOrJudgingASheetFailsWithoutOutput) {
    write_frames(2, 8, 6);
    auto r = run(kTonemap + " " + quote(dir.path("beauty.%04d.exr")) + " --frames 1-3 --contact-sheet -o " +
                 quote(dir.path("sheet.png")));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("beauty.0003.exr"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path("sheet.png")));
    r = run(kTonemap + " " + quote(dir.path("beauty.%04d.exr")) + " --frames 1-2 --contact-sheet --skip-existing -o " +
            quote(dir.path("sheet.png")));
    EXPECT_EQ(r.exit_code, 2);
    // Frames of different sizes cannot share a grid.
    write_exr(dir.path("beauty.0003.exr"), Image(9, 6, {"R", "G", "B"}, 0.5f));
    r = run(kTonemap + " " + quote(dir.path("beauty.%04d.exr")) + " --frames 1-3 --contact-sheet -o " +
            quote(dir.path("sheet.png")));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("one size"), std::string::npos) << r.err;
}
