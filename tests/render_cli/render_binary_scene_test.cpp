// orb-render reads the binary scene form (recognised by its magic) and
// renders exactly what it renders from the same scene as JSON; it reads PLY
// clouds too, through the same importer as orb-import.
#include <fstream>

#include "cli_fixture.h"
#include "orb/scene/scene_binary.h"

using namespace orb::test;
using orb::exr::testing::expect_same_pixels;
using orb::exr::testing::read_raw_exr;

TEST_F(RenderCli, BinarySceneRendersTheSamePixelsAsJson) {
    orb::Scene scene = small_scene();
    scene.spheres[0].name = "";  // one unnamed sphere among named ones
    const std::string json_file = write_scene(scene);
    const std::string binary_file = path("scene.orb");
    std::ofstream(binary_file, std::ios::binary) << orb::write_scene_binary(scene);

    const auto from_json = render({json_file, "-o", path("json.exr"), "--seed", "11", "--spp", "3"});
    ASSERT_EQ(from_json.exit_code, 0) << from_json.err;
    const auto from_binary = render({binary_file, "-o", path("binary.exr"), "--seed", "11", "--spp", "3"});
    ASSERT_EQ(from_binary.exit_code, 0) << from_binary.err;

    expect_same_pixels(read_raw_exr(path("json.exr")), read_raw_exr(path("binary.exr")));
}

TEST_F(RenderCli, BrokenBinarySceneIsOneErrorAndNoImage) {
    std::string bytes = orb::write_scene_binary(small_scene());
    bytes.resize(bytes.size() - 5);
    std::ofstream(path("broken.orb"), std::ios::binary) << bytes;
    const auto run = render({path("broken.orb"), "-o", path("out.exr")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_NE(run.err.find("broken.orb: truncated"), std::string::npos) << run.err;
    EXPECT_EQ(files(), std::vector<std::string>{"broken.orb"});
}

TEST_F(RenderCli, PlyCloudRendersWithItsAutomaticCameraAndLights) {
    std::ofstream(path("cloud.ply"), std::ios::binary)
        << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
           "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n"
           "0 0 0 255 255 255\n1 0 0 255 0 0\n0 1 0 0 255 0\n";
    const auto run = render({path("cloud.ply"), "-o", path("cloud.exr"), "--width", "16", "--height", "12", "--spp", "2"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto raw = read_raw_exr(path("cloud.exr"));
    double total = 0;
    for (float v : raw.channels.at("R")) total += v;
    EXPECT_GT(total, 0.0) << "the default lights must light the cloud the camera sees";
}
