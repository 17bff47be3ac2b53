// orb-diff's FLIP against NVIDIA's reference implementation (flip-evaluator)
// on the same files: mean FLIP must agree within 1e-3.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <regex>

#include "test_support.h"

using namespace orb::image;
using namespace orb::image::test;

namespace {

double reference_mean_flip(const std::string& ref, const std::string& test) {
    const auto r = run(quote(flip_evaluator()) + " -r " + quote(ref) + " -t " + quote(test) + " -v 1 -nerm -nexm");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::smatch m;
    const std::regex mean_line("Mean: *([0-9.eE+-]+)");
    if (!std::regex_search(r.out, m, mean_line)) {
        ADD_FAILURE() << "no mean in flip output: " << r.out << r.err;
        return NAN;
    }
    return std::stod(m[1]);
}

nlohmann::json orb_report(const std::string& ref, const std::string& test) {
    const auto r = run(quote(diff_exe()) + " " + quote(ref) + " " + quote(test) + " --json - -q");
    EXPECT_LE(r.exit_code, 1) << r.err;
    return nlohmann::json::parse(r.out);
}

Image clamped(Image img) {
    for (float& v : img.pixels) v = std::clamp(v, 0.0f, 1.0f);
    return img;
}

Image box_blur(const Image& in, int radius) {
    Image out = in;
    for (int y = 0; y < in.height; ++y)
        for (int x = 0; x < in.width; ++x)
            for (int c = 0; c < in.channels(); ++c) {
                float sum = 0;
                int n = 0;
                for (int dy = -radius; dy <= radius; ++dy)
                    for (int dx = -radius; dx <= radius; ++dx) {
                        const int sx = std::clamp(x + dx, 0, in.width - 1), sy = std::clamp(y + dy, 0, in.height - 1);
                        sum += in.at(sx, sy, c);
                        ++n;
                    }
                out.at(x, y, c) = sum / n;
            }
    return out;
}

Image scaled(Image img, float r, float g, float b) {
    for (size_t p = 0; p < img.pixel_count(); ++p) {
        img.pixels[p * 3] *= r;
        img.pixels[p * 3 + 1] *= g;
        img.pixels[p * 3 + 2] *= b;
    }
    return img;
}

void expect_agreement(const std::string& ref, const std::string& test, const char* variant) {
    const double expected = reference_mean_flip(ref, test);
    const auto report = orb_report(ref, test);
    const auto& flip = report["passes"][0]["metrics"]["flip"];
    ASSERT_TRUE(flip.is_object()) << report.dump(2);
    EXPECT_EQ(flip["variant"], variant);
    EXPECT_NEAR(flip["mean"].get<double>(), expected, 1e-3) << ref << " vs " << test;
    EXPECT_GT(expected, 0.0);  // the pairs do differ
}

}  // namespace

TEST(FlipReference, LdrPairsMatchNvidiaFlip) {
    ScratchDir dir;
    const Image ref = clamped(make_scene(96, 64, 0.4f));
    write_png(dir.path("ref.png"), ref);
    write_png(dir.path("noise.png"), clamped(make_scene(96, 64, 0.4f, 0.08f, 7)));
    write_png(dir.path("heavy_noise.png"), clamped(make_scene(96, 64, 0.4f, 0.4f, 9)));
    write_png(dir.path("blur.png"), box_blur(ref, 2));
    write_png(dir.path("tint.png"), clamped(scaled(ref, 1.2f, 0.9f, 0.7f)));
    for (const char* test : {"noise.png", "heavy_noise.png", "blur.png", "tint.png"})
        expect_agreement(dir.path("ref.png"), dir.path(test), "LDR-FLIP");
}

TEST(FlipReference, HdrPairsMatchNvidiaFlip) {
    ScratchDir dir;
    const Image ref = make_scene(96, 64, 12.0f);
    write_exr(dir.path("ref.exr"), ref);
    write_exr(dir.path("noise.exr"), make_scene(96, 64, 12.0f, 0.1f, 3));
    write_exr(dir.path("brighter.exr"), scaled(ref, 1.5f, 1.5f, 1.5f));
    write_exr(dir.path("tint.exr"), scaled(ref, 1.0f, 0.8f, 1.3f));
    write_exr(dir.path("blur.exr"), box_blur(ref, 1));
    for (const char* test : {"noise.exr", "brighter.exr", "tint.exr", "blur.exr"})
        expect_agreement(dir.path("ref.exr"), dir.path(test), "HDR-FLIP");
}
