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

// Frame 1 is read (and styled) once: for the plan, which hands it to its pose.
TEST_F(RenderTrajectory, EachFrameIsReadOnce) {
    const std::string xyz = write_trajectory();
    const auto run = render({xyz, "--frames", "1-3", "--radius-scale", "0.5", "--spp", "1", "--width", "16",
                             "--height", "12", "-o", path("w.%04d.exr")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("; 3 frames read from " + xyz + "\n"), std::string::npos) << run.err;
    // Frame 1 alone, and frames in another order: still each once.
    const auto reversed = render({xyz, "--frames", "3,2,1", "--spp", "1", "--width", "16", "--height", "12", "-o",
                                  path("r.%04d.exr")});
    ASSERT_EQ(reversed.exit_code, 0) << reversed.err;
    EXPECT_NE(reversed.err.find("; 3 frames read from " + xyz + "\n"), std::string::npos) << reversed.err;
    // The frame handed over is the frame as read and styled: the same scene whatever the order.
    EXPECT_NE(read_film_exr(path("r.0001.exr")).metadata.scene_hash, read_film_exr(path("w.0001.exr")).metadata.scene_hash)
        << "--radius-scale styles the frames of the first run only";
    const auto styled = render({xyz, "--frames", "2,1", "--radius-scale", "0.5", "--spp", "1", "--width", "16",
                                "--height", "12", "-o", path("c.%04d.exr")});
    ASSERT_EQ(styled.exit_code, 0) << styled.err;
    EXPECT_EQ(read_film_exr(path("c.0001.exr")).metadata.scene_hash, read_film_exr(path("w.0001.exr")).metadata.scene_hash);
    EXPECT_EQ(read_film_exr(path("c.0002.exr")).metadata.scene_hash, read_film_exr(path("w.0002.exr")).metadata.scene_hash);
}

// A numbered series is the trajectory of its files, frame k the k-th file by number: the same
// scenes (orb:sceneHash) as the one file holding all the frames.
TEST_F(RenderTrajectory, ANumberedSeriesRendersAsTheFileOfItsFrames) {
    const std::string xyz = write_trajectory();
    const char* frames[] = {"3\nframe 1\nO 0 0 0\nH 0.76 0.59 0\nH -0.76 0.59 0\n",
                            "3\nframe 2\nO 0 0.3 0\nH 0.76 0.89 0\nH -0.76 0.89 0\n",
                            "2\nframe 3\nO 0 0.6 0\nH 0.76 1.19 0\n"};
    fs::create_directories(path("series"));
    for (int k = 0; k < 3; ++k) std::ofstream(path("series/water." + std::to_string(100 * k) + ".xyz")) << frames[k];
    std::ofstream(path("series/water.300.xyz.orig")) << frames[2];  // not of the series (another name)
    const std::string pattern = path("series/water.*.xyz");
    const auto series = render({pattern, "--frames", "1-3", "--spp", "1", "--width", "16", "--height", "12", "-o",
                                path("s.%04d.exr")});
    ASSERT_EQ(series.exit_code, 0) << series.err;
    EXPECT_NE(series.err.find("; 3 frames read from " + pattern), std::string::npos) << series.err;
    const auto whole = render({xyz, "--frames", "1-3", "--spp", "1", "--width", "16", "--height", "12", "-o",
                               path("w.%04d.exr")});
    ASSERT_EQ(whole.exit_code, 0) << whole.err;
    for (const char* frame : {"0001", "0002", "0003"}) {
        const auto a = read_film_exr(path(std::string("s.") + frame + ".exr"));
        const auto b = read_film_exr(path(std::string("w.") + frame + ".exr"));
        EXPECT_EQ(a.metadata.scene_hash, b.metadata.scene_hash) << frame;
        EXPECT_EQ(a.metadata.world_to_camera, b.metadata.world_to_camera) << frame;
    }
    // A gap is one error before anything renders.
    fs::rename(path("series/water.300.xyz.orig"), path("series/water.300.xyz"));
    fs::remove(path("series/water.100.xyz"));
    const auto gap = render({pattern, "--frames", "1-2", "--spp", "1", "-o", path("g.%04d.exr")});
    EXPECT_EQ(gap.exit_code, 1);
    EXPECT_EQ(gap.err, "orb-render: error: " + pattern + ": " + path("series/water.100.xyz") +
                           " is missing: the series steps by 100, and " + path("series/water.0.xyz") +
                           " is followed by " + path("series/water.200.xyz") + "\n");
    EXPECT_FALSE(fs::exists(path("g.0001.exr")));
}

TEST_F(RenderTrajectory, AFramePastTheEndIsOneErrorBeforeAnythingRenders) {
    const std::string xyz = write_trajectory();
    const auto run = render({xyz, "--frames", "2-4", "--spp", "1", "-o", path("w.%04d.exr")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err, "orb-render: error: " + xyz + ": has 3 frames (1-3); there is no frame 4 (frame 1 is the file's first)\n");
    EXPECT_FALSE(fs::exists(path("w.0002.exr")));
}

// An error met in one frame names it: chemfiles' extended XYZ has the property
// CS_1 in its first two frames only, and frame 3 is where --color-by CS_1 fails.
TEST_F(RenderTrajectory, AnErrorInAFrameNamesTheFrame) {
    const std::string xyz = std::string(ORB_TEST_DATA_DIR) + "/chemfiles-tests-data/extended.xyz";
    const auto run = render({xyz, "--color-by", "CS_1", "--frames", "1-3", "--spp", "1", "--width", "16", "--height",
                             "12", "-o", path("x.%04d.exr")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_NE(run.err.find("orb-render: error: frame 3: " + xyz + ": --color-by CS_1: no such sphere property"),
              std::string::npos)
        << run.err;
    EXPECT_TRUE(fs::exists(path("x.0002.exr")));
    EXPECT_FALSE(fs::exists(path("x.0003.exr")));
    // The first frame's own error names it too.
    const auto first = render({xyz, "--color-by", "nosuch", "--frames", "1-3", "--spp", "1", "-o", path("y.%04d.exr")});
    EXPECT_EQ(first.exit_code, 1);
    EXPECT_NE(first.err.find("orb-render: error: frame 1: " + xyz + ": --color-by nosuch: no such sphere property"),
              std::string::npos)
        << first.err;
}

}  // namespace
