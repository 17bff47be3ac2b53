// A molecular trajectory is an animation: frame f of --frames is the file's
// frame f (from 1), each read from the file, under frame 1's camera; a frame
// past the end is one error before anything renders; finished frames are
// left alone as for any animation.
#include <filesystem>
#include <fstream>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"

using namespace orb::test;
using orb::exr::read_film_exr;
namespace fs = std::filesystem;

namespace {

// Three frames: a water molecule that moves, then loses an atom.
const char* kTrajectory =
    "3\nframe 1\nO 0 0 0\nH 0.76 0.59 0\nH -0.76 0.59 0\n"
    "3\nframe 2\nO 0 0.3 0\nH 0.76 0.89 0\nH -0.76 0.89 0\n"
    "2\nframe 3\nO 0 0.6 0\nH 0.76 1.19 0\n";

class RenderTrajectory : public RenderCli {
protected:
    std::string write_trajectory() {
        const std::string file = path("water.xyz");
        std::ofstream(file) << kTrajectory;
        return file;
    }
};

TEST_F(RenderTrajectory, FrameFOfTheFileIsFrameFOfFrames) {
    const std::string xyz = write_trajectory();
    const auto run = render({xyz, "--frames", "1-3", "--spp", "1", "--width", "16", "--height", "12", "-o",
                             path("w.%04d.exr")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto first = read_film_exr(path("w.0001.exr"));
    const auto third = read_film_exr(path("w.0003.exr"));
    ASSERT_TRUE(third.metadata.frame.has_value());
    EXPECT_EQ(third.metadata.frame->number, 3);
    // Each frame is its own scene (its hash), under one camera.
    EXPECT_NE(first.metadata.scene_hash, third.metadata.scene_hash);
    EXPECT_EQ(first.metadata.world_to_camera, third.metadata.world_to_camera);
    // Finished frames are left alone, as for any animation.
    const auto again = render({xyz, "--frames", "1-3", "--spp", "1", "--width", "16", "--height", "12",
                               "--skip-existing", "-o", path("w.%04d.exr")});
    EXPECT_EQ(again.exit_code, 0) << again.err;
    EXPECT_NE(again.err.find("0 rendered, 3 finished already"), std::string::npos) << again.err;
}

TEST_F(RenderTrajectory, AFramePastTheEndIsOneErrorBeforeAnythingRenders) {
    const std::string xyz = write_trajectory();
    const auto run = render({xyz, "--frames", "2-4", "--spp", "1", "-o", path("w.%04d.exr")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err, "orb-render: error: " + xyz + ": has 3 frames (1-3); there is no frame 4 (frame 1 is the file's first)\n");
    EXPECT_FALSE(fs::exists(path("w.0002.exr")));
}

}  // namespace
