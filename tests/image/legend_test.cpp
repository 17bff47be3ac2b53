// The --color-by legend (orb/image/legend.h): its bar holds the colour map's
// colours at the positions it shows, its categories one swatch each in their
// colours; and the tools that take --color-by write it (--legend), or say
// clearly why not.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <OpenImageIO/imageio.h>

#include "orb/image/legend.h"
#include "orb/import/colormaps.h"
#include "orb/import/elements.h"
#include "test_support.h"

using namespace orb::image;
using namespace orb::image::test;
namespace fs = std::filesystem;

namespace {

orb::ColorLegend temperature_legend(orb::Colormap map = orb::Colormap::Viridis) {
    orb::ColorLegend legend;
    legend.property = "temperature";
    legend.colormap = map;
    legend.range = {300, 400};
    return legend;
}

orb::ColorLegend element_legend() {
    orb::ColorLegend legend;
    legend.property = "element";
    legend.categorical = true;
    for (const char* symbol : {"O", "H", "C"}) {
        const orb::Element* element = orb::find_element(symbol);
        legend.categories.push_back(
            {symbol, {element->jmol_srgb[0] / 255.0f, element->jmol_srgb[1] / 255.0f, element->jmol_srgb[2] / 255.0f}});
    }
    return legend;
}

// Dark pixels (text, ticks) in a box: the ground is white, the frames grey.
int ink_in(const Image& image, int x0, int y0, int x1, int y1) {
    int n = 0;
    for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y)
        for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x)
            n += image.at(x, y, 0) < 0.3f && image.at(x, y, 1) < 0.3f && image.at(x, y, 2) < 0.3f;
    return n;
}

// The position on the map of the bar's pixel along its length: its ends are the map's ends.
double expected_position(const PixelBox& bar, LegendOrientation orientation, int x, int y) {
    return orientation == LegendOrientation::Vertical ? double(bar.y1 - 1 - y) / (bar.y1 - bar.y0 - 1)
                                                      : double(x - bar.x0) / (bar.x1 - bar.x0 - 1);
}

void expect_bar_is_the_map(const Image& image, const PixelBox& bar, LegendOrientation orientation, orb::Colormap map,
                           float tolerance) {
    ASSERT_GT(bar.x1, bar.x0);
    ASSERT_GT(bar.y1, bar.y0);
    ASSERT_LE(bar.x1, image.width);
    ASSERT_LE(bar.y1, image.height);
    for (int y = bar.y0; y < bar.y1; ++y)
        for (int x = bar.x0; x < bar.x1; ++x) {
            const auto want = orb::colormap_display_color(map, expected_position(bar, orientation, x, y));
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(image.at(x, y, c), want[c], tolerance) << "at " << x << "," << y << " channel " << c;
        }
}

TEST(Legend, AVerticalBarHoldsTheMapWithTheLargestValueAtTheTop) {
    const LegendImage legend = draw_legend(temperature_legend(orb::Colormap::Magma), LegendOrientation::Vertical);
    EXPECT_EQ(legend.bar.y1 - legend.bar.y0, 256);
    EXPECT_TRUE(legend.swatches.empty());
    expect_bar_is_the_map(legend.image, legend.bar, LegendOrientation::Vertical, orb::Colormap::Magma, 1e-6f);
    const auto top = orb::colormap_display_color(orb::Colormap::Magma, 1.0);
    EXPECT_FLOAT_EQ(legend.image.at(legend.bar.x0, legend.bar.y0, 0), top[0]);
    // The name above the bar, the values beside it.
    EXPECT_GT(ink_in(legend.image, 0, 0, legend.image.width, legend.bar.y0 - 8), 20);
    EXPECT_GT(ink_in(legend.image, legend.bar.x1 + 8, 0, legend.image.width, legend.image.height), 60);
}

TEST(Legend, AHorizontalBarHoldsTheMapWithTheSmallestValueAtTheLeft) {
    const LegendImage legend = draw_legend(temperature_legend(), LegendOrientation::Horizontal);
    EXPECT_EQ(legend.bar.x1 - legend.bar.x0, 256);
    expect_bar_is_the_map(legend.image, legend.bar, LegendOrientation::Horizontal, orb::Colormap::Viridis, 1e-6f);
    EXPECT_GT(ink_in(legend.image, 0, legend.bar.y1 + 2, legend.image.width, legend.image.height), 60);
}

TEST(Legend, AnEmptyRangeDrawsOneValue) {
    orb::ColorLegend spec = temperature_legend();
    spec.range = {5, 5};
    const LegendImage legend = draw_legend(spec, LegendOrientation::Vertical);
    expect_bar_is_the_map(legend.image, legend.bar, LegendOrientation::Vertical, orb::Colormap::Viridis, 1e-6f);
}

TEST(Legend, EachCategoryIsASwatchOfItsColourBesideItsLabel) {
    const orb::ColorLegend spec = element_legend();
    for (LegendOrientation orientation : {LegendOrientation::Vertical, LegendOrientation::Horizontal}) {
        const LegendImage legend = draw_legend(spec, orientation);
        ASSERT_EQ(legend.swatches.size(), spec.categories.size());
        for (std::size_t k = 0; k < legend.swatches.size(); ++k) {
            const PixelBox& s = legend.swatches[k];
            ASSERT_GE(s.x0, 0);
            ASSERT_LE(s.x1, legend.image.width);
            ASSERT_LE(s.y1, legend.image.height);
            for (int y = s.y0; y < s.y1; ++y)
                for (int x = s.x0; x < s.x1; ++x)
                    for (int c = 0; c < 3; ++c)
                        ASSERT_EQ(legend.image.at(x, y, c), spec.categories[k].display_color[c]) << k;
            // Its label, right of it on its row.
            EXPECT_GT(ink_in(legend.image, s.x1 + 4, s.y0 - 4, s.x1 + 40, s.y1 + 4), 10) << spec.categories[k].label;
            for (std::size_t j = 0; j < k; ++j) {
                const PixelBox& o = legend.swatches[j];
                EXPECT_TRUE(s.x0 >= o.x1 || o.x0 >= s.x1 || s.y0 >= o.y1 || o.y0 >= s.y1) << "swatches overlap";
            }
        }
    }
}

TEST(Legend, ManyCategoriesWrapIntoColumns) {
    orb::ColorLegend spec;
    spec.property = "residue_number";
    spec.categorical = true;
    for (int k = 0; k < 45; ++k) {
        // Appended, not "r" + std::to_string(k): g++ 12 warns (-Wrestrict)
        // about its own inlined string operator+ and insert there, a false
        // positive of the compiler.
        std::string name(1, 'r');
        name += std::to_string(k);
        spec.categories.push_back({name, orb::qualitative_display_color(k)});
    }
    const LegendImage legend = draw_legend(spec, LegendOrientation::Vertical);
    ASSERT_EQ(legend.swatches.size(), 45u);
    EXPECT_EQ(legend.swatches[20].y0, legend.swatches[0].y0);  // a column holds 20
    EXPECT_GT(legend.swatches[20].x0, legend.swatches[19].x1);
    EXPECT_LE(legend.swatches[44].x1, legend.image.width);
}

// The PNG holds the drawn colours rounded to 8 bits: no dithering.
TEST(Legend, ThePngHoldsTheMapRoundedTo8Bits) {
    ScratchDir dir;
    const std::string png = encode_legend_png(temperature_legend(), LegendOrientation::Vertical);
    const std::string path = dir.path("legend.png");
    std::ofstream(path, std::ios::binary) << png;
    const Image read = read_image(path);
    const LegendImage drawn = draw_legend(temperature_legend(), LegendOrientation::Vertical);
    ASSERT_EQ(read.width, drawn.image.width);
    ASSERT_EQ(read.height, drawn.image.height);
    expect_bar_is_the_map(read, drawn.bar, LegendOrientation::Vertical, orb::Colormap::Viridis, 0.5f / 255 + 1e-6f);
}

std::string import_exe() { return ORB_IMPORT_EXE; }

// Water and methane: elements O, H, C; a numeric column for --color-by.
std::string write_molecules(const ScratchDir& dir) {
    const std::string path = dir.path("mols.xyz");
    std::ofstream(path) << "8\nProperties=species:S:1:pos:R:3:charge:R:1\n"
                           "O 0 0 0 -0.8\nH 0.76 0.59 0 0.4\nH -0.76 0.59 0 0.4\n"
                           "C 4 0 0 -0.4\nH 4.6 0.6 0.2 0.1\nH 3.4 0.6 -0.2 0.1\nH 4.2 -0.6 0.6 0.1\nH 3.8 -0.6 -0.6 0.1\n";
    return path;
}

TEST(LegendCli, OrbImportWritesTheLegendOfANumericProperty) {
    ScratchDir dir;
    const std::string xyz = write_molecules(dir);
    const auto r = run(quote(import_exe()) + " " + quote(xyz) + " --color-by charge --colormap coolwarm --legend " +
                       quote(dir.path("charge.png")) + " --legend-layout horizontal -o " + quote(dir.path("m.json")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("charge.png: legend of charge over coolwarm"), std::string::npos) << r.err;
    orb::ColorLegend spec;
    spec.property = "charge";
    spec.colormap = orb::Colormap::Coolwarm;
    spec.range = {-0.8, 0.4};
    const LegendImage drawn = draw_legend(spec, LegendOrientation::Horizontal);
    const Image read = read_image(dir.path("charge.png"));
    ASSERT_EQ(read.width, drawn.image.width);
    ASSERT_EQ(read.height, drawn.image.height);
    expect_bar_is_the_map(read, drawn.bar, LegendOrientation::Horizontal, orb::Colormap::Coolwarm,
                          0.5f / 255 + 1e-6f);
}

TEST(LegendCli, ACategoricalLegendHasASwatchPerCategoryTheParticlesHave) {
    ScratchDir dir;
    const std::string xyz = write_molecules(dir);
    const auto r = run(quote(import_exe()) + " " + quote(xyz) + " --color-by element --legend " +
                       quote(dir.path("elements.png")) + " -o " + quote(dir.path("m.json")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("elements.png: legend of 3 categories of element"), std::string::npos) << r.err;
    const orb::ColorLegend spec = element_legend();  // O, H, C: the order the file names them
    const LegendImage drawn = draw_legend(spec, LegendOrientation::Vertical);
    const Image read = read_image(dir.path("elements.png"));
    ASSERT_EQ(read.width, drawn.image.width);
    ASSERT_EQ(read.height, drawn.image.height);
    for (std::size_t k = 0; k < drawn.swatches.size(); ++k) {
        const PixelBox& s = drawn.swatches[k];
        const int x = (s.x0 + s.x1) / 2, y = (s.y0 + s.y1) / 2;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(read.at(x, y, c), spec.categories[k].display_color[c], 0.5f / 255 + 1e-6f) << k;
    }
}

TEST(LegendCli, ALegendNeedsColorByAndAPngName) {
    ScratchDir dir;
    const std::string xyz = write_molecules(dir);
    auto r = run(quote(import_exe()) + " " + quote(xyz) + " --legend " + quote(dir.path("l.png")) + " -o " +
                 quote(dir.path("m.json")));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("needs --color-by PROPERTY"), std::string::npos) << r.err;
    r = run(quote(import_exe()) + " " + quote(xyz) + " --color-by charge --legend " + quote(dir.path("l.jpg")) +
            " -o " + quote(dir.path("m.json")));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("expected a PNG file name"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.path("m.json")));
    EXPECT_FALSE(fs::exists(dir.path("l.png")));
}

TEST(LegendCli, AnUnwritableLegendIsAnErrorBeforeAnythingIsWritten) {
    ScratchDir dir;
    const std::string xyz = write_molecules(dir);
    const auto r = run(quote(import_exe()) + " " + quote(xyz) + " --color-by charge --legend " +
                       quote(dir.path("no/such/folder/l.png")) + " -o " + quote(dir.path("m.json")));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("no/such/folder/l.png"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir.path("m.json")));
}

TEST(LegendCli, ALegendIsNeverWrittenOverTheInput) {
    ScratchDir dir;
    const std::string xyz = write_molecules(dir);
    const std::string before = [&] { std::ifstream f(xyz); return std::string(std::istreambuf_iterator<char>(f), {}); }();
    fs::copy_file(xyz, dir.path("mols.png"));
    const auto r = run(quote(import_exe()) + " " + quote(dir.path("mols.png")) + " --from xyz --color-by charge --legend " +
                       quote(dir.path("mols.png")) + " -o " + quote(dir.path("m.json")));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    std::ifstream f(dir.path("mols.png"));
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(f), {}), before);
}

}  // namespace
