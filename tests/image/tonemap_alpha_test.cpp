// What a display image shows where the spheres do not cover a pixel
// (docs/design/background-and-alpha.md): opaque by default, --transparent,
// --background; each output format's alpha; and --auto-exposure.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <array>
#include <cmath>

#include "orb/image/auto_exposure.h"
#include "test_support.h"

using namespace orb::image;
using namespace orb::image::test;
namespace OIIO = OIIO_NAMESPACE;

namespace {

const std::string kTonemap = quote(tonemap_exe());

// The scene: spheres of colour S over an environment of radiance E, with
// coverages 1, 0, 1/4 and 1/2 (exact in binary, so every product is exact).
constexpr std::array<float, 3> kSphere = {0.25f, 0.5f, 0.75f};
constexpr std::array<float, 3> kEnvironment = {0.5f, 0.25f, 0.125f};
constexpr std::array<float, 4> kCoverage = {1.0f, 0.0f, 0.25f, 0.5f};

// An EXR laid out as orb-render writes it: RGB what the camera sees
// (A S + (1 - A) E), A the coverage, background.RGB the environment seen
// where nothing covers ((1 - A) E); orb:passes marks it as orb-render's.
// `with_background` false leaves that layer out; `orb_render` false writes a
// plain premultiplied RGBA file (RGB = A S) with no orb:passes.
void write_render(const std::string& path, bool with_background, bool orb_render = true) {
    std::vector<std::string> names = {"R", "G", "B", "A"};
    if (with_background) names.insert(names.end(), {"background.R", "background.G", "background.B"});
    OIIO::ImageSpec spec(4, 1, static_cast<int>(names.size()), OIIO::TypeDesc::FLOAT);
    spec.channelnames = names;
    spec.alpha_channel = 3;
    if (orb_render) spec.attribute("orb:passes", with_background ? "beauty,background" : "beauty");
    std::vector<float> pixels;
    for (float a : kCoverage) {
        for (int c = 0; c < 3; ++c) pixels.push_back(a * kSphere[c] + (orb_render ? (1 - a) * kEnvironment[c] : 0.0f));
        pixels.push_back(a);
        if (with_background)
            for (int c = 0; c < 3; ++c) pixels.push_back((1 - a) * kEnvironment[c]);
    }
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out && out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) && out->close());
}

// The stored values as they are: straight alpha is not premultiplied on reading.
Image read_stored(const std::string& path) {
    OIIO::ImageSpec hint;
    hint.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &hint);
    EXPECT_TRUE(in) << path;
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<std::string> names(spec.channelnames.begin(), spec.channelnames.end());
    Image image(spec.width, spec.height, names);
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()));
    return image;
}

std::string stored_attribute(const std::string& path, const std::string& name) {
    auto in = OIIO::ImageInput::open(path);
    return in ? in->spec().get_string_attribute(name) : "";
}

class TonemapAlpha : public ::testing::Test {
protected:
    ScratchDir dir;
    std::string render = dir.path("render.exr");
    void SetUp() override { write_render(render, true); }

    // The Raw view passes scene-linear values through, so each output value
    // is the compositing formula's; 16 bits holds it within half a code.
    Image tonemap(const std::string& options, const std::string& out, const std::string& view = "Raw") {
        const auto r = run(kTonemap + " " + quote(render) + " --view " + view + " " + options + " -o " + quote(dir.path(out)));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return read_stored(dir.path(out));
    }
};

constexpr double kHalfCode16 = 0.5 / 65535.0 + 1e-7;

}  // namespace

TEST_F(TonemapAlpha, OpaqueByDefaultShowsWhatTheCameraSees) {
    const Image png = tonemap("--bits 16", "opaque.png");
    ASSERT_EQ(png.channels(), 3);
    for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(png.at(x, 0, c), kCoverage[x] * kSphere[c] + (1 - kCoverage[x]) * kEnvironment[c], kHalfCode16)
                << "pixel " << x << " channel " << c;
}

TEST_F(TonemapAlpha, TransparentPngAndTiffHoldStraightColourOfTheSpheresAlone) {
    for (const std::string name : {"t.png", "t.tif"}) {
        const Image image = tonemap("--transparent --bits 16", name);
        ASSERT_EQ(image.channels(), 4) << name;
        for (int x = 0; x < 4; ++x) {
            EXPECT_NEAR(image.at(x, 0, 3), kCoverage[x], kHalfCode16) << name << " pixel " << x;
            if (kCoverage[x] == 0.0f) continue;  // no colour where nothing covers
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(image.at(x, 0, c), kSphere[c], kHalfCode16) << name << " pixel " << x << " channel " << c;
        }
    }
    // TIFF says its alpha is unassociated (ExtraSamples 2), so readers do not divide again.
    auto in = OIIO::ImageInput::open(dir.path("t.tif"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().get_int_attribute("tiff:UnassociatedAlpha", 0), 1);
}

TEST_F(TonemapAlpha, TransparentExrHoldsAssociatedColour) {
    const Image exr = tonemap("--transparent --bits 32", "t.exr");
    ASSERT_EQ(exr.channels(), 4);
    for (int x = 0; x < 4; ++x) {
        EXPECT_FLOAT_EQ(exr.at(x, 0, 3), kCoverage[x]);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(exr.at(x, 0, c), kCoverage[x] * kSphere[c], 1e-6) << x << "," << c;
    }
}

TEST_F(TonemapAlpha, TransparentUnpremultipliesBeforeTheViewSoEdgesAreNotDarkenedTwice) {
    // Standard view: the sRGB encoding of S at every covered pixel, whatever its coverage.
    const Image png = tonemap("--transparent --bits 16", "std.png", "Standard");
    auto srgb = [](double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055; };
    for (int x : {0, 2, 3})
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(png.at(x, 0, c), srgb(kSphere[c]), 2e-4) << x << "," << c;
}

TEST_F(TonemapAlpha, BackgroundCompositesTheSpheresOverAColourInSceneLinear) {
    const std::array<float, 3> plate = {0.125f, 0.375f, 0.0625f};
    const Image png = tonemap("--background 0.125,0.375,0.0625 --bits 16", "over.png");
    ASSERT_EQ(png.channels(), 3);
    for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(png.at(x, 0, c), kCoverage[x] * kSphere[c] + (1 - kCoverage[x]) * plate[c], kHalfCode16)
                << "pixel " << x << " channel " << c;
    // #rrggbb is sRGB-encoded: #808080 is 128/255 decoded, 0.2158605 in linear light.
    const Image hex = tonemap("--background '#808080' --bits 16", "hex.png");
    EXPECT_NEAR(hex.at(1, 0, 0), 0.2158605, kHalfCode16);
}

TEST_F(TonemapAlpha, OtherFilesArePremultipliedAsTheExrConventionSays) {
    write_render(render, false, /*orb_render=*/false);
    const Image png = tonemap("--transparent --bits 16", "plain.png");
    for (int x : {0, 2, 3})
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(png.at(x, 0, c), kSphere[c], kHalfCode16);
}

TEST_F(TonemapAlpha, AnOrbRenderWithoutItsBackgroundLayerIsNotMadeTransparentByGuessing) {
    write_render(render, false);
    for (const std::string option : {"--transparent", "--background 0,0,0"}) {
        const auto r = run(kTonemap + " " + quote(render) + " " + option + " -o " + quote(dir.path("x.png")));
        EXPECT_EQ(r.exit_code, 1) << option;
        EXPECT_NE(r.err.find("--passes beauty,background"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.path("x.png")));
    }
    // Opaque needs no background layer.
    EXPECT_EQ(run(kTonemap + " " + quote(render) + " -q -o " + quote(dir.path("x.png"))).exit_code, 0);
}

TEST_F(TonemapAlpha, BadBackgroundsAndContradictionsAreUsageErrors) {
    for (const std::string bad : {"1,2", "1,2,3,4", "-1,0,0", "nan,0,0", "#12345", "#12345g", "red", "1,,2"}) {
        const auto r = run(kTonemap + " " + quote(render) + " --background " + quote(bad) + " -o " + quote(dir.path("x.png")));
        EXPECT_EQ(r.exit_code, 2) << bad;
        EXPECT_NE(r.err.find("--background"), std::string::npos) << r.err;
    }
    EXPECT_EQ(run(kTonemap + " " + quote(render) + " --transparent --background 0,0,0 -o " + quote(dir.path("x.png"))).exit_code, 2);
    EXPECT_EQ(run(kTonemap + " " + quote(render) + " --transparent --contact-sheet -o " + quote(dir.path("x.png"))).exit_code, 2);
}

TEST_F(TonemapAlpha, TheRecordNamesTheAlphaAndSkipExistingTellsItApart) {
    tonemap("--transparent", "r.png");
    EXPECT_NE(stored_attribute(dir.path("r.png"), "orb:tonemap").find("alpha=transparent\n"), std::string::npos);
    const auto r = run(kTonemap + " " + quote(render) + " --view Raw --skip-existing -o " + quote(dir.path("r.png")));
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.err.find("made transparent, opaque asked"), std::string::npos) << r.err;
}

// ---- --auto-exposure ----

TEST(AutoExposure, MapsTheLogAverageLuminanceToMiddleGrey) {
    // Two grey pixels, 0.05 and 0.8: log-average sqrt(0.04) = 0.2; black and
    // non-finite pixels do not count.
    Image image(4, 1, {"R", "G", "B"});
    const float values[4] = {0.05f, 0.8f, 0.0f, INFINITY};
    for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 3; ++c) image.at(x, 0, c) = values[x];
    const AutoExposure a = auto_exposure(image, {0.2126, 0.7152, 0.0722});
    EXPECT_EQ(a.pixels, 2u);
    EXPECT_NEAR(a.log_average, 0.2, 1e-6);
    EXPECT_NEAR(a.stops, std::log2(0.18 / 0.2), 1e-6);
}

TEST(AutoExposure, UsesUnpremultipliedColourAndSkipsUncoveredPixels) {
    Image image(2, 1, {"R", "G", "B", "A"});
    for (int c = 0; c < 3; ++c) image.at(0, 0, c) = 0.09f;  // 0.36 at coverage 1/4
    image.at(0, 0, 3) = 0.25f;
    image.at(1, 0, 0) = 5.0f;  // alpha 0: not counted
    const AutoExposure a = auto_exposure(image, {0.2126, 0.7152, 0.0722});
    EXPECT_EQ(a.pixels, 1u);
    EXPECT_NEAR(a.stops, -1.0, 1e-5);
}

TEST(AutoExposure, AnAllBlackImageKeepsItsExposure) {
    const AutoExposure a = auto_exposure(Image(8, 8, {"R", "G", "B"}), {0.2126, 0.7152, 0.0722});
    EXPECT_EQ(a.pixels, 0u);
    EXPECT_EQ(a.stops, 0.0);
}

TEST(AutoExposureCli, ExposesAGreyImageToMiddleGreyAndAddsExposure) {
    ScratchDir dir;
    write_exr(dir.path("grey.exr"), Image(8, 4, {"R", "G", "B"}, 0.72f));
    auto r = run(kTonemap + " " + quote(dir.path("grey.exr")) + " --view Raw --auto-exposure --bits 16 -o " +
                 quote(dir.path("g.png")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("exposure -2 stops"), std::string::npos) << r.err;
    EXPECT_NEAR(read_stored(dir.path("g.png")).at(3, 2, 1), 0.18, kHalfCode16);
    r = run(kTonemap + " " + quote(dir.path("grey.exr")) + " --view Raw --auto-exposure --exposure 1 --bits 16 -o " +
            quote(dir.path("g1.png")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NEAR(read_stored(dir.path("g1.png")).at(3, 2, 1), 0.36, kHalfCode16);
    // All black: a warning, the exposure unchanged, an image all the same.
    write_exr(dir.path("black.exr"), Image(8, 4, {"R", "G", "B"}, 0.0f));
    r = run(kTonemap + " " + quote(dir.path("black.exr")) + " --auto-exposure -o " + quote(dir.path("b.png")));
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.err.find("no pixel brighter than black"), std::string::npos) << r.err;
}
