// Animations from one command: every frame at its time and seed, from one
// OpenCL session; frames that are done are left alone; machines sharing a
// folder split the frames through claims.
#include <unistd.h>

#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"

using namespace orb::test;
using orb::exr::read_film_exr;
using orb::exr::testing::read_raw_exr;
namespace fs = std::filesystem;

namespace {

std::string host_name() {
    char name[256] = {};
    ::gethostname(name, sizeof name - 1);
    return name;
}

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_F(RenderCli, FramesRenderEveryFrameAtItsTimeWithOneKernelBuild) {
    const std::string scene = write_scene(moving_ball_scene());
    const auto run = render({scene, "--frames", "1-3", "--spp", "2", "--passes", "beauty,id", "-o", path("beauty.%04d.exr")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("3 rendered, 0 finished already"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("(1 kernel build)"), std::string::npos) << run.err;
    EXPECT_EQ(count(run.err, "device: "), 1) << run.err;  // one session for all frames
    std::set<std::uint64_t> seeds;
    for (int frame = 1; frame <= 3; ++frame) {
        const std::string file = path("beauty.000" + std::to_string(frame) + ".exr");
        EXPECT_EQ(count(run.err, "frame " + std::to_string(frame) + ": done: 2 spp"), 1) << run.err;
        const auto image = read_film_exr(file);
        ASSERT_TRUE(image.metadata.frame.has_value());
        EXPECT_EQ(image.metadata.frame->number, frame);
        EXPECT_EQ(image.metadata.frame->fps, 24.0);
        EXPECT_DOUBLE_EQ(image.metadata.scene_time, frame / 24.0);
        seeds.insert(image.metadata.seed);
    }
    EXPECT_EQ(seeds.size(), 3u);  // noise differs from frame to frame
    // The ball moves: the frames are different images.
    EXPECT_NE(read_film_exr(path("beauty.0001.exr")).film.object_id,
              read_film_exr(path("beauty.0003.exr")).film.object_id);
}

TEST_F(RenderCli, OneFrameEqualsTheSameFrameOfASequence) {
    const std::string scene = write_scene(moving_ball_scene());
    ASSERT_EQ(render({scene, "--frames", "10-14x2", "--spp", "3", "--seed", "8", "-o", path("seq.####.exr")}).exit_code,
              0);
    const auto one = render({scene, "--frame", "12", "--spp", "3", "--seed", "8", "-o", path("one.exr")});
    ASSERT_EQ(one.exit_code, 0) << one.err;
    EXPECT_FALSE(fs::exists(path("seq.0011.exr")));
    const auto a = read_film_exr(path("seq.0012.exr"));
    const auto b = read_film_exr(path("one.exr"));
    EXPECT_EQ(a.metadata.seed, b.metadata.seed);
    EXPECT_EQ(a.metadata.scene_hash, b.metadata.scene_hash);
    expect_same_image(read_raw_exr(path("seq.0012.exr")), read_raw_exr(path("one.exr")));

    // --same-seed keeps --seed for every frame; --fps sets the time.
    ASSERT_EQ(render({scene, "--frame", "12", "--fps", "48", "--same-seed", "--spp", "1", "--seed", "8", "-o",
                      path("same.exr")})
                  .exit_code,
              0);
    const auto same = read_film_exr(path("same.exr"));
    EXPECT_EQ(same.metadata.seed, 8u);
    EXPECT_DOUBLE_EQ(same.metadata.scene_time, 0.25);
    EXPECT_EQ(same.metadata.frame->fps, 48.0);
}

TEST_F(RenderCli, FrameSlicesMergeToTheWholeFrame) {
    // What a farm does with a frame split into sample slices.
    const std::string scene = write_scene(moving_ball_scene());
    ASSERT_EQ(render({scene, "--frame", "5", "--spp", "6", "-o", path("whole.exr")}).exit_code, 0);
    ASSERT_EQ(render({scene, "--frame", "5", "--sample-range", "0:2", "-o", path("s0.%04d.exr")}).exit_code, 0);
    ASSERT_EQ(render({scene, "--frame", "5", "--sample-range", "2:4", "-o", path("s1.%04d.exr")}).exit_code, 0);
    const auto merged = merge({path("s0.0005.exr"), path("s1.0005.exr"), "-o", path("merged.exr")});
    ASSERT_EQ(merged.exit_code, 0) << merged.err;
    expect_same_image(read_raw_exr(path("whole.exr")), read_raw_exr(path("merged.exr")));
}

TEST_F(RenderCli, SkipExistingLeavesFinishedFramesContinuesPartialOnesAndRendersTheOthersAgain) {
    const std::string scene = write_scene(moving_ball_scene());
    ASSERT_EQ(render({scene, "--frames", "1-2", "--spp", "2", "-o", path("f.%04d.exr")}).exit_code, 0);
    // Frame 2 damaged (cut short), frame 3 interrupted: 1 of its 8 spp.
    fs::resize_file(path("f.0002.exr"), fs::file_size(path("f.0002.exr")) / 2);
    ASSERT_EQ(render({scene, "--frame", "3", "--spp", "8", "--time", "0.000001", "-o", path("f.0003.exr")}).exit_code, 0);
    ASSERT_LT(read_film_exr(path("f.0003.exr")).film.samples_per_pixel, 8u);
    const auto first_time = fs::last_write_time(path("f.0001.exr"));

    const auto run = render({scene, "--frames", "1-4", "--spp", "2", "-o", path("f.%04d.exr"), "--skip-existing"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("frame 1: " + path("f.0001.exr") + ": finished (2 spp); skipped"), std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("frame 2: " + path("f.0002.exr") + ": unreadable ("), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("): rendering again"), std::string::npos) << run.err;
    // 1 of 2 asked: the same render, continued (its own target of 8 is not what this run asks).
    EXPECT_NE(run.err.find("frame 3: " + path("f.0003.exr") + ": holds 1 of 2 spp: continuing it"), std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("3 rendered (1 continued), 1 finished already"), std::string::npos) << run.err;
    EXPECT_EQ(fs::last_write_time(path("f.0001.exr")), first_time);
    for (int frame = 2; frame <= 4; ++frame) {
        const auto film = read_film_exr(path("f.000" + std::to_string(frame) + ".exr"));
        EXPECT_EQ(film.film.sample_ranges.format(), "0:2") << frame;
        EXPECT_EQ(film.metadata.target_spp, 2u) << frame;
    }

    // All finished: nothing to render, no OpenCL set up at all.
    const auto again = render({scene, "--frames", "1-4", "--spp", "2", "-o", path("f.%04d.exr"), "--skip-existing"});
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(again.err.find("device: "), std::string::npos) << again.err;
    EXPECT_NE(again.err.find("0 rendered, 4 finished already"), std::string::npos) << again.err;
    // Fewer samples than a file holds: still finished.
    const auto fewer = render({scene, "--frames", "1-4", "--spp", "1", "-o", path("f.%04d.exr"), "--skip-existing"});
    EXPECT_NE(fewer.err.find("0 rendered, 4 finished already"), std::string::npos) << fewer.err;
}

TEST_F(RenderCli, ClaimsAreRespectedWhileAliveAndTakenOverWhenStale) {
    const std::string scene = write_scene(moving_ball_scene());
    const std::string here = host_name();
    std::ofstream(path("f.0001.exr.claim")) << "host " << here << " pid 999999999 started 0\n";  // died here
    std::ofstream(path("f.0002.exr.claim")) << "host " << here << " pid " << ::getpid() << " started 0\n";  // alive
    std::ofstream(path("f.0003.exr.claim")) << "host elsewhere.example pid 42 started 0\n";  // stale: see below
    std::ofstream(path("f.0004.exr.claim")) << "host elsewhere.example pid 42 started 0\n";  // fresh
    fs::last_write_time(path("f.0003.exr.claim"), fs::file_time_type::clock::now() - std::chrono::minutes(20));

    const auto run = render({scene, "--frames", "1-5", "--spp", "1", "-o", path("f.%04d.exr"), "--claim"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("f.0002.exr is claimed by host " + here + " pid " + std::to_string(::getpid())),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("f.0004.exr is claimed by host elsewhere.example pid 42"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("3 rendered, 0 finished already, 2 claimed elsewhere"), std::string::npos) << run.err;
    EXPECT_EQ(files(), (std::vector<std::string>{"f.0001.exr", "f.0002.exr.claim", "f.0003.exr", "f.0004.exr.claim",
                                                 "f.0005.exr", "scene.json"}));

    // A shorter --claim-stale-after takes the other host's claim over too.
    fs::last_write_time(path("f.0004.exr.claim"), fs::file_time_type::clock::now() - std::chrono::seconds(30));
    const auto later = render({scene, "--frame", "4", "--spp", "1", "-o", path("f.%04d.exr"), "--claim",
                               "--claim-stale-after", "10"});
    ASSERT_EQ(later.exit_code, 0) << later.err;
    EXPECT_TRUE(fs::exists(path("f.0004.exr")));
    EXPECT_FALSE(fs::exists(path("f.0004.exr.claim")));
}

TEST_F(RenderCli, TwoProcessesWithClaimsRenderEachFrameOnce) {
    const std::string scene = write_scene(moving_ball_scene());
    const std::vector<std::string> args{render_exe(), scene, "--frames", "1-8", "--spp", "2", "-o",
                                        path("f.%04d.exr"), "--claim"};
    Child a(args, path("a.log"));
    Child b(args, path("b.log"));
    const auto ra = a.wait(120), rb = b.wait(120);
    ASSERT_EQ(ra.exit_code, 0) << ra.err;
    ASSERT_EQ(rb.exit_code, 0) << rb.err;
    for (int frame = 1; frame <= 8; ++frame) {
        const std::string done = "frame " + std::to_string(frame) + ": done";
        EXPECT_EQ(count(ra.err, done) + count(rb.err, done), 1) << done << "\n" << ra.err << "\n" << rb.err;
        EXPECT_TRUE(fs::exists(path("f.000" + std::to_string(frame) + ".exr")));
        EXPECT_FALSE(fs::exists(path("f.000" + std::to_string(frame) + ".exr.claim")));
    }
}

TEST_F(RenderCli, ALogGetsProgressLinesAndOneLinePerFrame) {
    const std::string scene = write_scene(moving_ball_scene());
    // stderr is a file here, not a terminal.
    // A line is due each pass after the interval: 0.001 s is shorter than any
    // pass of 40 spp at 64x48 (a frame took 4-6 ms on PoCL with SIMD lanes).
    const auto run = render({scene, "--frames", "1-2", "--spp", "40", "--width", "64", "--height", "48",
                             "--progress-interval", "0.001", "-o", path("f.%04d.exr")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_GE(count(run.err, "frame 1: pass "), 1) << run.err;
    EXPECT_GE(count(run.err, "frame 2: pass "), 1) << run.err;
    EXPECT_EQ(count(run.err, "frame 1: done: 40 spp"), 1) << run.err;
    EXPECT_EQ(count(run.err, "frame 2: done: 40 spp"), 1) << run.err;
    EXPECT_EQ(run.err.find('\r'), std::string::npos);  // no redrawing in a log
}

TEST_F(RenderCli, FrameUsageErrors) {
    const std::string scene = write_scene(moving_ball_scene());
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"--frames", "1-3", "-o", path("plain.exr")},
             {"--frames", "1-3", "-o", "-"},
             {"--frame", "1", "--frames", "1-3", "-o", path("f.%04d.exr")},
             {"--frames", "1-3", "--time-at", "1", "-o", path("f.%04d.exr")},
             {"--frames", "3-1", "-o", path("f.%04d.exr")},
             {"--frames", "1-10x0", "-o", path("f.%04d.exr")},
             {"--frame", "-1", "-o", path("f.exr")},
             {"--fps", "30", "-o", path("f.exr")},
             {"--same-seed", "-o", path("f.exr")},
             {"--frames", "1-2", "--fps", "0", "-o", path("f.%04d.exr")},
             {"--frame", "1", "--claim", "-o", "-"},
             {"--frame", "1", "--resume", path("f.exr"), "-o", path("g.exr")},
         }) {
        std::vector<std::string> argv{scene};
        argv.insert(argv.end(), args.begin(), args.end());
        const auto run = render(argv);
        EXPECT_EQ(run.exit_code, 2) << ::testing::PrintToString(args) << ": " << run.err;
    }
    EXPECT_EQ(files(), (std::vector<std::string>{"scene.json"}));
    // A missing folder fails before any frame renders.
    const auto missing = render({scene, "--frames", "1-2", "-o", path("no/f.%04d.exr")});
    EXPECT_EQ(missing.exit_code, 1);
    EXPECT_NE(missing.err.find("does not exist"), std::string::npos) << missing.err;
    EXPECT_EQ(missing.err.find("device: "), std::string::npos) << missing.err;
}

// --benchmark --frames says where a frame's time goes (the render path, one
// frame's writing step by step, the writers' pace at 1 to N frames at once)
// and leaves none of its frames behind.
TEST_F(RenderCli, FramesBenchmarkBreaksAFrameDownAndLeavesNoFile) {
    const std::string scene = write_scene(moving_ball_scene());
    const std::string scratch = path("tmp");
    fs::create_directory(scratch);
    const char* old = std::getenv("TMPDIR");
    const std::string restore = old ? old : "";
    ::setenv("TMPDIR", scratch.c_str(), 1);
    const auto run = render({scene, "--benchmark", "--frames", "1-3", "--spp", "1"});
    if (old)
        ::setenv("TMPDIR", restore.c_str(), 1);
    else
        ::unsetenv("TMPDIR");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    for (const char* part : {"frames written at once", "render (1 spp)", "read back (started)", "wait for writer",
                             "the last writes", "the loop", "one frame written alone", "read back", "encode",
                             "write+fsync", "rename", "the writer alone", "1: "})
        EXPECT_NE(run.err.find(part), std::string::npos) << part << "\n" << run.err;
    EXPECT_NE(run.out.find("frame_overhead_ms="), std::string::npos) << run.out;
    EXPECT_TRUE(fs::is_empty(scratch));
}
