// A frame whose file cannot be written (a full disk: here /dev/full behind
// the frame's name, whose writes fail with ENOSPC) is named with why; a
// frame is said to be done only once its file is in place; the run stops
// with exit 1 naming every frame not written, and the frames written
// before stay.
#include <filesystem>
#include <regex>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"

using namespace orb::test;

TEST_F(RenderCli, FramesThatCannotBeWrittenAreEachNamedAndNeverSaidDone) {
    namespace fs = std::filesystem;
    const std::string scene = write_scene(moving_ball_scene());
    for (const char* full : {"b.0002.exr", "b.0003.exr"}) fs::create_symlink("/dev/full", path(full));
    const auto run = render({scene, "--frames", "1-4", "--spp", "2", "-o", path("b.%04d.exr")});
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_NE(run.err.find("frame 2: not written: "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("No space left on device"), std::string::npos) << run.err;
    for (int frame = 1; frame <= 4; ++frame) {
        const std::string name = path("b.000" + std::to_string(frame) + ".exr");
        const bool said_done = run.err.find("frame " + std::to_string(frame) + ": done") != std::string::npos;
        const bool not_written = run.err.find("frame " + std::to_string(frame) + ": not written") != std::string::npos;
        EXPECT_FALSE(said_done && not_written) << frame << ": " << run.err;
        // Done: its file is there, a whole image.
        if (said_done) {
            EXPECT_EQ(orb::exr::read_film_exr(name).film.samples_per_pixel, 2u) << frame;
        }
        // Not written: named again in the last line.
        if (not_written) {
            EXPECT_TRUE(std::regex_search(run.err, std::regex("images? not written \\([^)]*frame " +
                                                              std::to_string(frame) + "[,)]")))
                << frame << ": " << run.err;
        }
    }
    EXPECT_EQ(run.err.find("frame 2: done"), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find("frame 3: done"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("frame 1: done"), std::string::npos) << run.err;
    EXPECT_EQ(orb::exr::read_film_exr(path("b.0001.exr")).film.samples_per_pixel, 2u);
    // No temporary file or lock is left.
    for (const std::string& name : files()) EXPECT_NE(name.front(), '.') << name;
}
