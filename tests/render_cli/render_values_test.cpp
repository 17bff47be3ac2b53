// Values that cannot mean anything are refused before rendering (a seed
// outside 64 bits, a scene the device's floats cannot hold), and a resumed
// render passes orb-diff's default gate against an uninterrupted one.
#include <cstdint>
#include <filesystem>
#include <limits>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"

using namespace orb::test;

TEST_F(RenderCli, SeedOutsideSixtyFourBitsIsAUsageError) {
    const std::string scene = write_scene(small_scene());
    // -1 used to wrap to 2^64-1 and larger values to clamp, so seeds collided.
    for (const std::string seed : {"-1", "1.5", "18446744073709551616", "1e3", "+7", "0x10"}) {
        const auto run = render({scene, "-o", path("out.exr"), "--seed", seed});
        EXPECT_EQ(run.exit_code, 2) << seed << "\n" << run.err;
        EXPECT_EQ(run.err.rfind("orb-render: error: --seed: expected a whole number in [0, 18446744073709551615], got '" +
                                    seed + "'\n",
                                0),
                  0u)
            << run.err;
    }
    EXPECT_EQ(files(), std::vector<std::string>{"scene.json"});
}

TEST_F(RenderCli, SeedTakesTheWholeSixtyFourBitRange) {
    orb::Scene scene = small_scene();
    scene.render.width = 8;
    scene.render.height = 6;
    const auto run = render({write_scene(scene), "-o", path("out.exr"), "--spp", "1", "--seed", "18446744073709551615"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(orb::exr::read_film_exr(path("out.exr")).metadata.seed, std::numeric_limits<std::uint64_t>::max());
}

TEST_F(RenderCli, SceneBeyondTheDevicesFloatsIsRefused) {
    orb::Scene scene = small_scene();
    scene.spheres[1].radius = 1e300;  // would square to infinity in float: a vanished sphere
    const std::string file = write_scene(scene);
    const auto run = render({file, "-o", path("out.exr")});
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_EQ(run.err, "orb-render: error: " + file +
                           ": spheres[1].radius: must be in [1e-18, 1e+18] (the renderer computes in 32-bit floats), "
                           "got 1e+300\n");
    EXPECT_EQ(files(), std::vector<std::string>{"scene.json"});
}

TEST_F(RenderCli, AnimatedSceneLeavingTheLimitsWhenPosedIsRefused) {
    // Every keyframe is within the limits, but at 1 s the node scales the
    // bound sphere's radius 1e9 by 1e10.
    orb::Scene scene = small_scene();
    orb::AnimationNode node;
    orb::AnimationChannel grow;
    grow.path = orb::AnimationPath::Scale;
    grow.times = {0, 1};
    grow.values = {{1, 1, 1, 0}, {1e10, 1e10, 1e10, 0}};
    node.channels.push_back(grow);
    scene.animation.nodes.push_back(node);
    scene.animation.spheres.push_back({1, 0, {0, 0, 0}, 1e9});
    const std::string file = write_scene(scene);
    const auto run = render({file, "-o", path("out.exr"), "--time-at", "1"});
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_EQ(run.err, "orb-render: error: " + file +
                           " at 1 s: spheres[1].radius: must be in [1e-18, 1e+18] (the renderer computes in 32-bit "
                           "floats), got 1e+19\n");
    EXPECT_EQ(files(), std::vector<std::string>{"scene.json"});
}

TEST_F(RenderCli, ResumedRenderPassesTheDefaultDiffGate) {
    // A bright lamp, so that rounding differences exceed an absolute 1e-6.
    orb::Scene bright = small_scene();
    bright.materials[3].emission = {1200.0, 1100.0, 900.0};
    const std::string scene = write_scene(bright);
    ASSERT_EQ(render({scene, "-o", path("whole.exr"), "--spp", "16", "--seed", "5"}).exit_code, 0);
    ASSERT_EQ(render({scene, "-o", path("part.exr"), "--spp", "5", "--seed", "5"}).exit_code, 0);
    const auto resumed = render({scene, "--resume", path("part.exr"), "-o", path("resumed.exr"), "--spp", "16"});
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    ASSERT_EQ(render({scene, "-o", path("other.exr"), "--spp", "16", "--seed", "6"}).exit_code, 0);

    // The sums were added in another order: float rounding only.
    const auto same = run_process({ORB_DIFF_EXE, path("whole.exr"), path("resumed.exr")});
    EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
    EXPECT_NE(same.out.find("verdict: pass"), std::string::npos) << same.out;
    // The old default, any channel off by more than 1e-6, failed this pair.
    const auto absolute = run_process({ORB_DIFF_EXE, path("whole.exr"), path("resumed.exr"), "--fail-threshold", "1e-6"});
    EXPECT_EQ(absolute.exit_code, 1) << absolute.out << absolute.err;
    // Another seed is a real change.
    const auto changed = run_process({ORB_DIFF_EXE, path("whole.exr"), path("other.exr")});
    EXPECT_EQ(changed.exit_code, 1) << changed.out << changed.err;
    EXPECT_NE(changed.out.find("verdict: fail"), std::string::npos) << changed.out;
}
