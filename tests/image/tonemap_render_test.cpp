// A real render lit by a real HDR environment map (ILM's Kerner parking lot,
// tests/data/openexr-images), through orb-render and orb-tonemap: the
// default PNG shows the environment, opaque; --transparent keeps the ball
// alone; --background puts exactly that colour where the ball does not cover.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "test_support.h"

using namespace orb::image;
using namespace orb::image::test;
namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

namespace {

const std::string kTonemap = quote(tonemap_exe());

Image read_straight(const std::string& path) {
    OIIO::ImageSpec hint;
    hint.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &hint);
    EXPECT_TRUE(in) << path;
    const OIIO::ImageSpec& spec = in->spec();
    Image image(spec.width, spec.height, std::vector<std::string>(spec.channelnames.begin(), spec.channelnames.end()));
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()));
    return image;
}

class RenderUnderAnEnvironmentMap : public ::testing::Test {
protected:
    static inline ScratchDir* dir = nullptr;
    static inline std::string exr;
    static void SetUpTestSuite() {
        dir = new ScratchDir;
        fs::copy_file(std::string(ORB_TEST_DATA_DIR) + "/openexr-images/kerner-latlong-256x128.exr",
                      dir->path("kerner.exr"));
        // A grey ball filling the middle of a 48 x 32 view; the map all around it.
        std::ofstream(dir->path("scene.json")) << R"({
  "format": "orb-scene", "version": 1,
  "camera": { "position": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "vfov_deg": 40 },
  "render": { "width": 48, "height": 32, "spp": 16, "max_depth": 4 },
  "materials": [ { "name": "grey", "type": "diffuse", "color": [0.5, 0.5, 0.5] } ],
  "spheres": [ { "name": "ball", "center": [0, 0, 0], "radius": 1, "material": 0 } ],
  "environment": { "map": "kerner.exr" }
})";
        exr = dir->path("render.exr");
        const auto r = run(quote(ORB_RENDER_EXE) + " " + quote(dir->path("scene.json")) +
                           " --passes beauty,background -q -o " + quote(exr));
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    static void TearDownTestSuite() {
        delete dir;
        dir = nullptr;
    }
    Image tonemap(const std::string& options, const std::string& name) {
        const auto r = run(kTonemap + " " + quote(exr) + " " + options + " -q -o " + quote(dir->path(name)));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return read_straight(dir->path(name));
    }
};

}  // namespace

TEST_F(RenderUnderAnEnvironmentMap, TheDefaultImageShowsTheEnvironmentOpaque) {
    const Image render = read_image(exr);
    const Image png = tonemap("--bits 16", "default.png");
    ASSERT_EQ(png.channels(), 3) << "opaque: no alpha";
    // The corners see only the map: alpha 0 in the render, yet not black in the picture.
    const int a = render.find_channel("A");
    for (auto [x, y] : {std::pair{0, 0}, std::pair{47, 0}, std::pair{0, 31}, std::pair{47, 31}}) {
        ASSERT_EQ(render.at(x, y, a), 0.0f);
        EXPECT_GT(png.at(x, y, 0) + png.at(x, y, 1) + png.at(x, y, 2), 0.05) << x << "," << y;
    }
}

TEST_F(RenderUnderAnEnvironmentMap, TransparentKeepsTheBallAloneAndBackgroundFillsTheRest) {
    const Image render = read_image(exr);
    const int a = render.find_channel("A");
    const Image opaque = tonemap("--bits 16", "o.png");
    const Image alone = tonemap("--transparent --bits 16", "t.png");
    ASSERT_EQ(alone.channels(), 4);
    const Image over = tonemap("--background 0.25,0.5,0.125 --view Raw --bits 16", "b.png");
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 48; ++x) {
            const float coverage = render.at(x, y, a);
            ASSERT_NEAR(alone.at(x, y, 3), coverage, 0.5 / 65535 + 1e-7);
            if (coverage == 1.0f) {  // the ball covers the pixel: the same colour either way
                for (int c = 0; c < 3; ++c) ASSERT_NEAR(alone.at(x, y, c), opaque.at(x, y, c), 1.0 / 65535);
            }
            if (coverage == 0.0f) {  // nothing covers it: exactly the background colour
                ASSERT_NEAR(over.at(x, y, 0), 0.25, 0.5 / 65535 + 1e-7);
                ASSERT_NEAR(over.at(x, y, 1), 0.5, 0.5 / 65535 + 1e-7);
                ASSERT_NEAR(over.at(x, y, 2), 0.125, 0.5 / 65535 + 1e-7);
            }
        }
}

// Without environment light nothing but the spheres is in RGB, and orb-render
// says so (orb:environmentSeen 0): the default beauty layer alone makes a
// transparent image and takes a background colour, while a render under a
// map without the background layer is refused (the test above renders one).
TEST(RenderWithoutEnvironment, TheBeautyLayerAloneIsPremultipliedAndMakesATransparentImage) {
    ScratchDir dir;
    std::ofstream(dir.path("scene.json")) << R"({
  "format": "orb-scene", "version": 1,
  "camera": { "position": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "vfov_deg": 40 },
  "render": { "width": 48, "height": 32, "spp": 16, "max_depth": 4 },
  "materials": [ { "name": "glow", "type": "diffuse", "color": [0, 0, 0], "emission": [0.25, 0.5, 0.75] } ],
  "spheres": [ { "name": "ball", "center": [0, 0, 0], "radius": 1, "material": 0 } ]
})";
    const std::string exr = dir.path("render.exr");
    const auto rendered = run(quote(ORB_RENDER_EXE) + " " + quote(dir.path("scene.json")) + " -q -o " + quote(exr));
    ASSERT_EQ(rendered.exit_code, 0) << rendered.err;
    auto in = OIIO::ImageInput::open(exr);
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().get_int_attribute("orb:environmentSeen", -1), 0);
    in.reset();

    const Image render = read_image(exr);
    const int a = render.find_channel("A");
    auto tonemap = [&](const std::string& options, const std::string& name) {
        const auto r = run(kTonemap + " " + quote(exr) + " " + options + " -q -o " + quote(dir.path(name)));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return read_straight(dir.path(name));
    };
    const Image alone = tonemap("--transparent --view Raw --bits 16", "t.png");
    const Image over = tonemap("--background 0.5,0.25,0.125 --view Raw --bits 16", "b.png");
    ASSERT_EQ(alone.channels(), 4);
    int edges = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 48; ++x) {
            const float coverage = render.at(x, y, a);
            ASSERT_NEAR(alone.at(x, y, 3), coverage, 0.5 / 65535 + 1e-7);
            const float background[3] = {0.5f, 0.25f, 0.125f};
            for (int c = 0; c < 3; ++c) {
                // RGB is premultiplied: over a colour C the pixel is RGB + (1 - A)·C (Raw view, 16-bit rounding).
                const double expected = std::min(1.0, double(render.at(x, y, c)) + (1.0 - coverage) * background[c]);
                ASSERT_NEAR(over.at(x, y, c), expected, 0.5 / 65535 + 1e-6) << x << "," << y << " channel " << c;
                // Straight colour where covered: the ball's radiance, edges included.
                if (coverage > 0.0f) {
                    ASSERT_NEAR(alone.at(x, y, c), std::min(1.0, double(render.at(x, y, c)) / coverage),
                                0.5 / 65535 + 1e-5) << x << "," << y;
                }
            }
            edges += coverage > 0.0f && coverage < 1.0f;
        }
    EXPECT_GT(edges, 0) << "the ball's silhouette crosses some pixels";
}
