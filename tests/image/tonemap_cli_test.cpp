// orb-tonemap end to end, against oiiotool's own OCIO path on the same config.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "test_support.h"

using namespace orb::image;
using namespace orb::image::test;
namespace fs = std::filesystem;

namespace {

const std::string kTonemap = quote(tonemap_exe());

// Largest |ours - clamp(theirs)| over RGB.
double max_difference(const Image& ours, const Image& theirs) {
    double worst = 0;
    for (int y = 0; y < ours.height; ++y)
        for (int x = 0; x < ours.width; ++x)
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::fabs(static_cast<double>(ours.at(x, y, c)) -
                                                  std::clamp(theirs.at(x, y, c), 0.0f, 1.0f)));
    return worst;
}

// oiiotool's path for the same display/view; `extra_before` runs first (in scene-linear).
std::string oiiotool_display(const std::string& in, const std::string& display, const std::string& view,
                             const std::string& out, const std::string& extra_before = "") {
    return "oiiotool --colorconfig " + quote(ocio_config()) + " " + quote(in) + " " + extra_before +
           " --ociodisplay " + quote(display) + " " + quote(view) + " -d float -o " + quote(out);
}

class TonemapCli : public ::testing::Test {
protected:
    ScratchDir dir;
    std::string input = dir.path("scene.exr");
    void SetUp() override { write_exr(input, make_scene(64, 48, 6.0f)); }
};

}  // namespace

TEST_F(TonemapCli, EightBitOutputMatchesOiiotoolForEveryDisplayAndView) {
    for (const std::string display : {"sRGB", "Display P3", "Rec.1886"}) {
        for (const std::string view : {"Standard", "Filmic", "ACES 1.0 - SDR Video", "Raw"}) {
            const std::string ours = dir.path("ours.png"), theirs = dir.path("theirs.exr");
            auto r = run(kTonemap + " " + quote(input) + " --display " + quote(display) + " --view " + quote(view) +
                         " -o " + quote(ours) + " -q");
            ASSERT_EQ(r.exit_code, 0) << r.err;
            r = run(oiiotool_display(input, display, view, theirs));
            ASSERT_EQ(r.exit_code, 0) << r.err;
            EXPECT_LE(max_difference(read_image(ours), read_image(theirs)), 1.0 / 255.0 + 1e-6)
                << display << " / " << view;
        }
    }
}

TEST_F(TonemapCli, LooksAndExposureMatchOiiotool) {
    const std::string ours = dir.path("ours.png"), theirs = dir.path("theirs.exr");
    auto r = run(kTonemap + " " + quote(input) + " --look 'High Contrast' --exposure 1 -o " + quote(ours) + " -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // oiiotool 2.4 ignores --ociodisplay:looks= (measured: its output equals the
    // look-free view), so apply the look with its own --ociolook step instead.
    const std::string linear = quote("Linear Rec.709 (sRGB)");
    r = run(oiiotool_display(input, "sRGB", "Standard", theirs,
                             "--mulc 2 --ociolook:from=" + linear + ":to=" + linear + " 'High Contrast'"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_LE(max_difference(read_image(ours), read_image(theirs)), 1.0 / 255.0 + 1e-6);
}

TEST_F(TonemapCli, SixteenBitAndFloatOutputsAreFiner) {
    const std::string theirs = dir.path("theirs.exr");
    ASSERT_EQ(run(oiiotool_display(input, "sRGB", "Filmic", theirs)).exit_code, 0);
    const Image reference = read_image(theirs);
    ASSERT_EQ(run(kTonemap + " " + quote(input) + " --view Filmic --bits 16 -o " + quote(dir.path("o16.tif")) + " -q").exit_code, 0);
    EXPECT_LE(max_difference(read_image(dir.path("o16.tif")), reference), 1e-4);
    ASSERT_EQ(run(kTonemap + " " + quote(input) + " --view Filmic --bits 32 -o " + quote(dir.path("o32.exr")) + " -q").exit_code, 0);
    EXPECT_LE(max_difference(read_image(dir.path("o32.exr")), reference), 1e-4);
}

TEST_F(TonemapCli, FormatsByExtension) {
    for (const std::string name : {"a.png", "a.jpg", "a.tif", "a.exr"}) {
        const auto r = run(kTonemap + " " + quote(input) + " -o " + quote(dir.path(name)) + " -q");
        ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
        const Image img = read_image(dir.path(name));
        EXPECT_EQ(img.width, 64);
        EXPECT_EQ(img.height, 48);
    }
}

TEST_F(TonemapCli, FormatsWithoutAlphaGetRgb) {
    const std::string with_alpha = dir.path("rgba.exr");
    write_exr(with_alpha, make_multipass(16, 8));  // has an A channel
    // The writers OIIO says cannot hold alpha, and BMP (whose alpha readers ignore).
    for (const std::string name : {"a.hdr", "a.jpg", "a.ppm", "a.pnm", "a.bmp"}) {
        const auto r = run(kTonemap + " " + quote(with_alpha) + " --transparent -o " + quote(dir.path(name)));
        ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
        EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;
        EXPECT_EQ(read_image(dir.path(name)).channels(), 3) << name;
    }
    // Formats that hold alpha keep it with --transparent; by default every image is opaque.
    for (const std::string name : {"a.png", "a.tif", "a.exr"}) {
        ASSERT_EQ(run(kTonemap + " " + quote(with_alpha) + " --transparent -o " + quote(dir.path(name)) + " -q").exit_code, 0) << name;
        EXPECT_EQ(read_image(dir.path(name)).channels(), 4) << name;
        ASSERT_EQ(run(kTonemap + " " + quote(with_alpha) + " -o " + quote(dir.path(name)) + " -q").exit_code, 0) << name;
        EXPECT_EQ(read_image(dir.path(name)).channels(), 3) << name;
    }
}

TEST_F(TonemapCli, StdinToStdoutGivesTheSamePixels) {
    ASSERT_EQ(run(kTonemap + " " + quote(input) + " -o " + quote(dir.path("file.png")) + " -q").exit_code, 0);
    const auto r = run("cat " + quote(input) + " | " + kTonemap + " - -o - --format png -q > " + quote(dir.path("pipe.png")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_image(dir.path("pipe.png")).pixels, read_image(dir.path("file.png")).pixels);
}

TEST_F(TonemapCli, StdoutNeedsAFormat) {
    const auto r = run(kTonemap + " " + quote(input) + " -o -");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--format"), std::string::npos);
}

TEST_F(TonemapCli, PassesAndContactSheet) {
    const std::string multi = dir.path("multi.exr");
    const Image all = make_multipass(48, 32);
    write_exr(multi, all, true);
    ASSERT_EQ(run(kTonemap + " " + quote(multi) + " --pass normal -o " + quote(dir.path("n.png")) + " -q").exit_code, 0);
    const Image n = read_image(dir.path("n.png"));
    // 0.5 + 0.5 n, quantised (half-float input: allow its rounding too).
    EXPECT_NEAR(n.at(0, 0, 0), 0.5f + 0.5f * all.at(0, 0, all.find_channel("N.X")), 1.0 / 255 + 1e-3);
    EXPECT_NEAR(n.at(47, 31, 1), 0.5f + 0.5f * all.at(47, 31, all.find_channel("N.Y")), 1.0 / 255 + 1e-3);

    const auto r = run(kTonemap + " " + quote(multi) + " --contact-sheet -o " + quote(dir.path("sheet.png")) + " -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image sheet = read_image(dir.path("sheet.png"));
    // Nine passes: a 3x3 grid of 48x32 tiles plus labels and gaps.
    EXPECT_GT(sheet.width, 3 * 48);
    EXPECT_GT(sheet.height, 3 * 32);

    const auto missing = run(kTonemap + " " + quote(input) + " --pass direct -o " + quote(dir.path("d.png")));
    EXPECT_EQ(missing.exit_code, 1);
    EXPECT_NE(missing.err.find("no 'direct' pass"), std::string::npos);
}

TEST_F(TonemapCli, FrameSequencesKeepGoingPastABadFrame) {
    write_exr(dir.path("f.0001.exr"), make_scene(16, 8, 2.0f));
    write_exr(dir.path("f.0003.exr"), make_scene(16, 8, 3.0f));
    const auto r = run(kTonemap + " " + quote(dir.path("f.%04d.exr")) + " --frames 1-3 -o " + quote(dir.path("o.%04d.png")) + " -q");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("f.0002.exr"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir.path("o.0001.png")));
    EXPECT_FALSE(fs::exists(dir.path("o.0002.png")));
    EXPECT_TRUE(fs::exists(dir.path("o.0003.png")));
}

TEST_F(TonemapCli, SeveralInputsIntoADirectory) {
    write_exr(dir.path("b.exr"), make_scene(16, 8, 2.0f));
    fs::create_directory(dir.path("out"));
    const auto r = run(kTonemap + " " + quote(input) + " " + quote(dir.path("b.exr")) + " -o " + quote(dir.path("out")) + " --format jpg -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir.path("out/scene.jpg")));
    EXPECT_TRUE(fs::exists(dir.path("out/b.jpg")));
}

TEST_F(TonemapCli, BadInputsFailCleanlyWithoutPartialOutput) {
    std::ifstream in(input, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(dir.path("trunc.exr"), std::ios::binary).write(bytes.data(), bytes.size() / 2);
    std::ofstream(dir.path("junk.exr")) << "this is not an image";
    for (const std::string bad : {"trunc.exr", "junk.exr", "missing.exr"}) {
        const auto r = run(kTonemap + " " + quote(dir.path(bad)) + " -o " + quote(dir.path("out.png")));
        EXPECT_EQ(r.exit_code, 1) << bad;
        EXPECT_NE(r.err.find(bad), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir.path("out.png")));
    }
    const auto r = run("printf 'garbage' | " + kTonemap + " - -o " + quote(dir.path("out.png")));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("<stdin>"), std::string::npos);
    // No temporaries left behind.
    for (const auto& entry : fs::directory_iterator(dir.path("")))
        EXPECT_EQ(entry.path().filename().string().find(".out.png"), std::string::npos);
}

TEST_F(TonemapCli, MeaninglessExposureOrBitsAreUsageErrors) {
    struct Case {
        std::string option, value, message;
    };
    const std::vector<Case> cases = {
        {"--exposure", "nan", "expected a number of stops in [-100, 100], got 'nan'"},
        {"--exposure", "inf", "expected a number of stops in [-100, 100], got 'inf'"},
        {"--exposure", "-inf", "expected a number of stops in [-100, 100], got '-inf'"},
        {"--exposure", "1e6", "expected a number of stops in [-100, 100], got '1e6'"},
        {"--bits", "12", "expected 8, 16 or 32, got '12'"},
        {"--bits", "0", "expected 8, 16 or 32, got '0'"},
    };
    for (const Case& c : cases) {
        const auto r = run(kTonemap + " " + quote(input) + " -o " + quote(dir.path("out.png")) + " " + c.option + " " + c.value);
        EXPECT_EQ(r.exit_code, 2) << c.option << " " << c.value << "\n" << r.err;
        EXPECT_EQ(r.err.rfind("orb-tonemap: error: " + c.option + ": " + c.message + "\n", 0), 0u) << r.err;
        EXPECT_FALSE(fs::exists(dir.path("out.png")));
    }
    for (const auto& entry : fs::directory_iterator(dir.path("")))
        EXPECT_EQ(entry.path().filename().string(), "scene.exr");
}

// --bits that the output's format cannot hold is a command-line mistake:
// exit 2 before any work, no file.
TEST_F(TonemapCli, BitsTheFormatCannotHoldAreUsageErrors) {
    struct Case {
        std::string output, bits, message;
    };
    const std::vector<Case> cases = {
        {"out.jpg", "16", "JPEG holds only 8 bits per channel"},
        {"out.png", "32", "PNG holds 8 or 16 bits per channel"},
        {"out.exr", "8", "EXR holds 16-bit half or 32-bit float, not 8 bits"},
    };
    for (const Case& c : cases) {
        const auto r = run(kTonemap + " " + quote(input) + " --bits " + c.bits + " -o " + quote(dir.path(c.output)));
        EXPECT_EQ(r.exit_code, 2) << c.output << "\n" << r.err;
        EXPECT_EQ(r.err, "orb-tonemap: error: " + c.message + "\n");
        EXPECT_FALSE(fs::exists(dir.path(c.output)));
    }
}

TEST_F(TonemapCli, ListHonoursOcioAndConfigOverrides) {
    auto r = run(kTonemap + " --list");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* expected : {"sRGB", "Display P3", "Rec.1886", "Standard", "Filmic", "ACES 1.0 - SDR Video",
                                 "High Contrast", "Linear Rec.709 (sRGB)", "ACEScg"})
        EXPECT_NE(r.out.find(expected), std::string::npos) << expected;

    // A studio config: same content with a renamed display.
    std::ifstream in(ocio_config());
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("  Rec.1886:\n"), 12, "  Studio Monitor:\n");
    std::ofstream(dir.path("studio.ocio")) << text;
    r = run("OCIO=" + quote(dir.path("studio.ocio")) + " " + kTonemap + " --list");
    EXPECT_NE(r.out.find("Studio Monitor"), std::string::npos) << r.out << r.err;
    r = run("OCIO=/nonexistent.ocio " + kTonemap + " --config " + quote(dir.path("studio.ocio")) + " --list");
    EXPECT_NE(r.out.find("Studio Monitor"), std::string::npos) << r.out << r.err;
    r = run("OCIO=/nonexistent.ocio " + kTonemap + " --list");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("/nonexistent.ocio"), std::string::npos);

    r = run(kTonemap + " " + quote(input) + " --view Nope -o " + quote(dir.path("x.png")));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("Filmic"), std::string::npos);  // lists the valid views
}
