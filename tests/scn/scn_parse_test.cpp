// What the .scn reader accepts and the scene it builds from it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "orb/import/scn.h"
#include "scn_test_util.h"

namespace orb {
namespace {

constexpr const char* kTwoSpheres =
    "camera 50 45 205.6  50 44.957388 204.6\n"
    "size 2\n"
    "sphere 16.5  27 16.5 47  0 0 0  0.9 0.9 0.9  1\n"
    "sphere 3  50 66.6 81.6  12 12 12  0 0 0  0\n";

TEST(ScnParse, ReadsCameraSpheresAndMaterials) {
    const Scene scene = parse_scn(kTwoSpheres, "t.scn");
    EXPECT_EQ(scene.camera.position, (Vec3{50, 45, 205.6}));
    EXPECT_EQ(scene.camera.target, (Vec3{50, 44.957388, 204.6}));
    ASSERT_EQ(scene.spheres.size(), 2u);
    ASSERT_EQ(scene.materials.size(), 2u);

    const Sphere& mirror = scene.spheres[0];
    EXPECT_EQ(mirror.radius, 16.5);
    EXPECT_EQ(mirror.center, (Vec3{27, 16.5, 47}));
    EXPECT_EQ(scene.materials[mirror.material].type, MaterialType::Mirror);
    EXPECT_EQ(scene.materials[mirror.material].color, (Vec3{0.9, 0.9, 0.9}));
    EXPECT_EQ(scene.materials[mirror.material].emission, (Vec3{0, 0, 0}));

    const Sphere& light = scene.spheres[1];
    EXPECT_EQ(scene.materials[light.material].type, MaterialType::Diffuse);
    EXPECT_EQ(scene.materials[light.material].emission, (Vec3{12, 12, 12}));
    EXPECT_EQ(scene.materials[light.material].color, (Vec3{0, 0, 0}));
}

TEST(ScnParse, FramingIsSmallptGpus) {
    const Scene scene = parse_scn(kTwoSpheres, "t.scn");
    EXPECT_EQ(scene.camera.up, (Vec3{0, 1, 0}));
    // The image plane at unit distance is pi/4 high.
    const double half_height = std::tan(scene.camera.vfov_deg * std::numbers::pi / 360.0);
    EXPECT_NEAR(2.0 * half_height, std::numbers::pi / 4.0, 1e-12);
    EXPECT_NEAR(scene.camera.vfov_deg, 42.87978, 1e-5);  // 2 atan(pi/8) in degrees
    EXPECT_EQ(scene.camera.aperture, 0.0);
    EXPECT_EQ(scene.render, RenderSettings{});  // 640x480 and the other defaults
    EXPECT_EQ(scene.render.width, 640);
    EXPECT_EQ(scene.render.height, 480);
}

TEST(ScnParse, GlassHasIor15) {
    const Scene scene = parse_scn("camera 0 0 1 0 0 0\nsize 1\nsphere 1 0 0 0 0 0 0 1 1 1 2\n", "t.scn");
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].type, MaterialType::Dielectric);
    EXPECT_EQ(scene.materials[0].ior, 1.5);
}

TEST(ScnParse, NumbersAsStrtodReadsThem) {
    const Scene scene = parse_scn("camera 1e5 +2 .75  -0.5E-3 5. 1E+2\nsize +1\nsphere 2.5e0 -1 +0 0.0 0 0 0 .5 0.25 1 0\n",
                                  "t.scn");
    EXPECT_EQ(scene.camera.position, (Vec3{100000, 2, 0.75}));
    EXPECT_EQ(scene.camera.target, (Vec3{-0.0005, 5, 100}));
    ASSERT_EQ(scene.spheres.size(), 1u);
    EXPECT_EQ(scene.spheres[0].radius, 2.5);
    EXPECT_EQ(scene.materials[0].color, (Vec3{0.5, 0.25, 1}));
}

TEST(ScnParse, UnderflowReadsAsStrtodDoes) {
    const Scene scene = parse_scn("camera 0 0 1  1e-400 0 0\nsize 0\n", "t.scn");
    EXPECT_EQ(scene.camera.target[0], 0.0);
}

TEST(ScnParse, WhitespaceIsFree) {
    const Scene reference = parse_scn(kTwoSpheres, "t.scn");
    const char* variants[] = {
        // tabs, runs of spaces, leading and trailing whitespace
        "\tcamera\t50 45 205.6\t\t50 44.957388 204.6   \n  size 2\t\n"
        "sphere\t16.5 27 16.5 47 0 0 0 0.9 0.9 0.9 1\t\nsphere 3 50 66.6 81.6 12 12 12 0 0 0 0",
        // CRLF line ends
        "camera 50 45 205.6 50 44.957388 204.6\r\nsize 2\r\nsphere 16.5 27 16.5 47 0 0 0 0.9 0.9 0.9 1\r\n"
        "sphere 3 50 66.6 81.6 12 12 12 0 0 0 0\r\n",
        // blank lines everywhere, and lines of only whitespace
        "\n\ncamera 50 45 205.6 50 44.957388 204.6\n\n \t \nsize 2\n\nsphere 16.5 27 16.5 47 0 0 0 0.9 0.9 0.9 1\n\r\n"
        "sphere 3 50 66.6 81.6 12 12 12 0 0 0 0\n\n\n",
        // no final newline, CRLF without final newline
        "camera 50 45 205.6 50 44.957388 204.6\r\nsize 2\r\nsphere 16.5 27 16.5 47 0 0 0 0.9 0.9 0.9 1\r\n"
        "sphere 3 50 66.6 81.6 12 12 12 0 0 0 0",
        // a UTF-8 byte-order mark, as some Windows editors write
        "\xEF\xBB\xBF"
        "camera 50 45 205.6 50 44.957388 204.6\nsize 2\nsphere 16.5 27 16.5 47 0 0 0 0.9 0.9 0.9 1\n"
        "sphere 3 50 66.6 81.6 12 12 12 0 0 0 0\n",
    };
    for (const char* text : variants) EXPECT_EQ(parse_scn(text, "t.scn"), reference) << text;
}

TEST(ScnParse, SizeZeroIsAnEmptyScene) {
    const Scene scene = parse_scn("camera 0 0 1 0 0 0\nsize 0\n", "t.scn");
    EXPECT_TRUE(scene.spheres.empty());
    EXPECT_TRUE(scene.materials.empty());
}

TEST(ScnParse, SpheresThatLookAlikeShareOneMaterial) {
    const Scene scene = parse_scn(
        "camera 0 0 1 0 0 0\nsize 4\n"
        "sphere 1 0 0 0  0 0 0  0.75 0 0  0\n"
        "sphere 2 0 0 0  0 0 0  0.75 0 0  0\n"
        "sphere 3 0 0 0  0 0 0  0.75 0 0  1\n"  // same colour, other type
        "sphere 4 0 0 0  1 0 0  0.75 0 0  0\n",  // same colour, emits
        "t.scn");
    ASSERT_EQ(scene.materials.size(), 3u);
    EXPECT_EQ(scene.spheres[0].material, scene.spheres[1].material);
    EXPECT_NE(scene.spheres[0].material, scene.spheres[2].material);
    EXPECT_NE(scene.spheres[0].material, scene.spheres[3].material);
}

TEST(ScnParse, NegativeZeroKeepsItsOwnMaterialSoNumbersRoundTrip) {
    const Scene scene = parse_scn("camera 0 0 1 0 0 0\nsize 2\nsphere 1 0 0 0 0 0 0 0 0 0 0\nsphere 1 0 0 0 -0 0 0 0 0 0 0\n",
                                  "t.scn");
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_TRUE(std::signbit(scene.materials[scene.spheres[1].material].emission[0]));
}

TEST(ScnParse, NamesAreHelpfulAndUnique) {
    const Scene scene = parse_scn(
        "camera 0 0 1 0 0 0\nsize 7\n"
        "sphere 1 0 0 0  0 0 0  0.75 0.25 0.25  0\n"
        "sphere 1 0 0 0  0 0 0  0 0.75 0  0\n"
        "sphere 1 0 0 0  0 0 0  0.75 0.75 0.75  0\n"
        "sphere 1 0 0 0  0 0 0  0.9 0.9 0.9  1\n"
        "sphere 1 0 0 0  0 0 0  0 0 0.9  2\n"
        "sphere 1 0 0 0  12 12 12  0 0 0  0\n"
        "sphere 1 0 0 0  0 0 0  0.8 0.8 0.8  0\n",
        "t.scn");
    ASSERT_EQ(scene.materials.size(), 7u);
    EXPECT_EQ(scene.materials[0].name, "red diffuse");
    EXPECT_EQ(scene.materials[1].name, "green diffuse");
    EXPECT_EQ(scene.materials[2].name, "white diffuse");
    EXPECT_EQ(scene.materials[3].name, "white mirror");
    EXPECT_EQ(scene.materials[4].name, "blue glass");
    EXPECT_EQ(scene.materials[5].name, "light");
    EXPECT_EQ(scene.materials[6].name, "white diffuse 2");
    EXPECT_EQ(scene.spheres[0].name, "sphere 1");
    EXPECT_EQ(scene.spheres[6].name, "sphere 7");
}

}  // namespace
}  // namespace orb
