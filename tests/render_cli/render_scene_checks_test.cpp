// What orb-render says about a scene before rendering it: a scene without
// spheres or a file in a format Orb does not read is refused (exit 1, no
// image), and a run of frames that would render the same image again and
// again is pointed out once. --missing renders nothing, so the frame
// warnings are checked without a device.
#include <filesystem>
#include <fstream>

#include "cli_fixture.h"

using namespace orb::test;
namespace fs = std::filesystem;

namespace {

int count_of(const std::string& text, const std::string& what) {
    int n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_F(RenderCli, ASceneWithoutSpheresIsRefusedUnlessAllowEmpty) {
    orb::Scene sky = small_scene();
    sky.spheres.clear();
    sky.environment.kind = orb::EnvironmentKind::Color;
    sky.environment.color = {0.5, 0.5, 0.5};
    const std::string scene = write_scene(sky);
    const auto refused = render({scene, "-o", path("sky.exr")});
    EXPECT_EQ(refused.exit_code, 1);
    EXPECT_EQ(refused.err, "orb-render: error: " + scene +
                               ": no spheres: its \"spheres\" list is empty; --allow-empty accepts a scene without spheres\n");
    EXPECT_FALSE(fs::exists(path("sky.exr")));
    const auto allowed = render({scene, "--allow-empty", "--spp", "1", "-o", path("sky.exr")});
    EXPECT_EQ(allowed.exit_code, 0) << allowed.err;
    EXPECT_TRUE(fs::exists(path("sky.exr")));
}

TEST_F(RenderCli, AFormatOrbDoesNotReadIsNamed) {
    std::ofstream(path("tri.obj")) << "# Blender v2.77 (sub 0) OBJ File: ''\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const auto run = render({path("tri.obj"), "-o", path("tri.exr")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err, "orb-render: error: " + path("tri.obj") +
                           ": unsupported format (Wavefront OBJ); Orb reads .scn, .gltf/.glb, .ply, .json, .orb, .pdb/.ent, .cif/.mmcif, .xyz/.extxyz, .lammpstrj/.dump, .gro\n");
    EXPECT_FALSE(fs::exists(path("tri.exr")));
}

TEST_F(RenderCli, FramesOfAStaticSceneAreSaidToBeOneImage) {
    const std::string scene = write_scene(small_scene());
    const auto run = render({scene, "--frames", "1-3", "--missing", "-o", path("b.%04d.exr")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(count_of(run.err, "orb-render: warning: " + scene +
                                    ": the scene has no animation: all 3 frames are the same image\n"),
              1)
        << run.err;
    // One frame of a static scene is a still: nothing to say.
    const auto one = render({scene, "--frame", "2", "--missing", "-o", path("b.%04d.exr")});
    EXPECT_EQ(one.err.find("warning"), std::string::npos) << one.err;
}

TEST_F(RenderCli, FramesPastTheAnimationsEndAreNamed) {
    // The ball moves for 1 s: frames 0 ... 24 at 24 fps.
    const std::string scene = write_scene(moving_ball_scene());
    const auto run = render({scene, "--frames", "20-30", "--missing", "-o", path("b.%04d.exr")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(count_of(run.err, "orb-render: warning: " + scene +
                                    ": the animation ends at 1 s, at frame 24 (24 fps): the 6 frames from 25 to 30 "
                                    "hold its last pose\n"),
              1)
        << run.err;
    const auto one = render({scene, "--frame", "30", "--missing", "-o", path("b.%04d.exr")});
    EXPECT_NE(one.err.find(": the animation ends at 1 s, at frame 24 (24 fps): frame 30 holds its last pose\n"),
              std::string::npos)
        << one.err;
    const auto slow = render({scene, "--frames", "1-12", "--fps", "10", "--missing", "-o", path("b.%04d.exr")});
    EXPECT_NE(slow.err.find(": the animation ends at 1 s, at frame 10 (10 fps): the 2 frames from 11 to 12 hold its "
                            "last pose\n"),
              std::string::npos)
        << slow.err;
    const auto inside = render({scene, "--frames", "0-24", "--missing", "-o", path("b.%04d.exr")});
    EXPECT_EQ(inside.err.find("warning"), std::string::npos) << inside.err;
}

TEST_F(RenderCli, ColourByAPropertyOfTheSceneOrRefuseNamingTheOnesItHas) {
    orb::Scene scene = small_scene();
    std::vector<float> values;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) values.push_back(static_cast<float>(i));
    scene.sphere_attributes.properties = {{"charge", values, {}}};
    const std::string file = write_scene(scene);
    const auto unknown = render({file, "--color-by", "mass", "--spp", "1", "-o", path("x.exr")});
    EXPECT_EQ(unknown.exit_code, 1);
    EXPECT_EQ(unknown.err, "orb-render: error: " + file + ": --color-by mass: no such sphere property (the scene has: charge)\n");
    EXPECT_FALSE(fs::exists(path("x.exr")));
    EXPECT_EQ(render({file, "--colormap", "rainbow", "--color-by", "charge", "-o", path("x.exr")}).exit_code, 2);
    const auto styled = render({file, "--color-by", "charge", "--colormap", "cividis", "--spp", "1", "-o", path("x.exr")});
    EXPECT_EQ(styled.exit_code, 0) << styled.err;
    EXPECT_TRUE(fs::exists(path("x.exr")));
}
