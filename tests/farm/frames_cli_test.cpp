// orb-frames run as a real executable: frame lists and paths for shell loops,
// and --missing, which decides what orb-farm submits, on real orb-render EXRs.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "process.h"

namespace fs = std::filesystem;
using orb::test::ProcessResult;
using orb::test::run_process;
using ::testing::HasSubstr;

namespace {

const std::string kScene = std::string(ORB_SCENES_DIR) + "/bounce.gltf";

class FramesCli : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("orb-frames-cli-" + std::to_string(::getpid())) / info->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    ProcessResult frames(std::vector<std::string> args, const std::string& stdin_path = "") const {
        args.insert(args.begin(), ORB_FRAMES_EXE);
        return run_process(args, stdin_path);
    }

    // A small render of the example animation into `name` (8x6 pixels).
    void render(const std::string& name, std::vector<std::string> extra) const {
        std::vector<std::string> args{ORB_RENDER_EXE, kScene, "--width", "8", "--height", "6", "-q", "-o", path(name)};
        args.insert(args.end(), extra.begin(), extra.end());
        const ProcessResult r = run_process(args);
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }

    fs::path dir_;
};

TEST_F(FramesCli, PrintsTheFramesOfAListInOrder) {
    const ProcessResult r = frames({"1-7x3,2,4"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, "1\n4\n7\n2\n");
}

TEST_F(FramesCli, PrintsPathsOfAPattern) {
    const ProcessResult r = frames({"9-11", "shots/beauty.####.exr", "--paths"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, "shots/beauty.0009.exr\nshots/beauty.0010.exr\nshots/beauty.0011.exr\n");
}

TEST_F(FramesCli, ReadsTheListFromStdin) {
    std::ofstream(path("list")) << "3\n1 2,\n\n10-11\n";
    const ProcessResult r = frames({"-"}, path("list"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, "3\n1\n2\n10\n11\n");
}

TEST_F(FramesCli, UsageErrors) {
    struct Case {
        std::vector<std::string> args;
        std::string message;
    };
    const std::vector<Case> cases = {
        {{"3-1"}, "frame list '3-1': the range 3-1 ends before it starts"},
        {{"1-3", "beauty.exr", "--paths"}, "'beauty.exr' has no frame number"},
        {{"1-3", "--paths"}, "--paths needs a PATTERN"},
        {{"1-3", "--missing"}, "--missing needs a PATTERN"},
        {{"1-3", "b.%04d.exr", "--spp", "4"}, "the render's options (--spp, --width, --passes, ...) go with --missing"},
        {{"1-3", "b.%04d.exr", "--scene", "s.json"}, "go with --missing"},
        {{"1-3", "b.%04d.exr", "--allow-empty"}, "go with --missing"},
        {{"1-3", "b.%04d.exr", "--missing", "--passes", "beauty,bogus"}, "--passes: "},
        {{"1-3", "b.%04d.exr", "--missing", "--sample-range", "0:2", "--spp", "2"}, "drop --spp"},
        {{"1-3", "b.%04d.exr", "--missing", "--mode", "local"}, "--mode"},
        {{"1-3", "b.%s.exr", "--paths"}, "the only % conversions"},
        {{"1-3", "b.%04d.exr", "--missing", "--spp", "0"}, "--spp"},
    };
    for (const Case& c : cases) {
        const ProcessResult r = frames(c.args);
        EXPECT_EQ(r.exit_code, 2) << c.message << "\n" << r.err;
        EXPECT_THAT(r.err, HasSubstr(c.message));
        EXPECT_EQ(r.out, "");
    }
    const ProcessResult empty = frames({"-"});  // stdin is /dev/null
    EXPECT_EQ(empty.exit_code, 2);
    EXPECT_THAT(empty.err, HasSubstr("no frames on stdin"));
}

TEST_F(FramesCli, MissingRefusesASceneWithoutSpheresAsOrbRenderDoes) {
    const std::string sky = path("sky.json");
    std::ofstream(sky) << R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,5], "target": [0,0,0] },
        "environment": { "color": [1, 1, 1] }, "materials": [], "spheres": [] })";
    const ProcessResult refused = frames({"1-2", path("f.%04d.exr"), "--missing", "--scene", sky});
    EXPECT_EQ(refused.exit_code, 1);
    EXPECT_EQ(refused.err, "orb-frames: error: " + sky +
                               ": no spheres: its \"spheres\" list is empty; --allow-empty accepts a scene without spheres\n");
    EXPECT_EQ(refused.out, "");
    const ProcessResult allowed = frames({"1-2", path("f.%04d.exr"), "--missing", "--scene", sky, "--allow-empty"});
    EXPECT_EQ(allowed.exit_code, 0) << allowed.err;
    EXPECT_EQ(allowed.out, "1\n2\n");
}

TEST_F(FramesCli, MissingNamesFramesThatAreNotCompleteRenders) {
    render("f.0001.exr", {"--frame", "1", "--spp", "2"});                    // complete
    render("f.0003.exr", {"--frame", "3", "--spp", "2"});                    // complete, then cut short below
    render("f.0004.exr", {"--frame", "4", "--spp", "100000", "--time", "0.05"});  // stopped by its time limit
    std::ofstream(path("f.0005.exr")) << "not an EXR";
    fs::create_directory(path("f.0006.exr"));
    // Frame 2 is absent. Frame 3 loses its last bytes (a copy that died half way).
    const auto size = fs::file_size(path("f.0003.exr"));
    fs::resize_file(path("f.0003.exr"), size - 64);

    const ProcessResult r = frames({"1-6", path("f.%04d.exr"), "--missing"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, "2\n3\n4\n5\n6\n");
    // Files that exist but do not count are explained; an absent one is not.
    EXPECT_THAT(r.err, HasSubstr("frame 4: " + path("f.0004.exr") + ": holds "));
    EXPECT_THAT(r.err, HasSubstr(" of 100000 spp"));
    EXPECT_THAT(r.err, HasSubstr("frame 5: " + path("f.0005.exr") + ": unreadable (not an OpenEXR file)"));
    EXPECT_THAT(r.err, HasSubstr("frame 6: " + path("f.0006.exr") + ": unreadable (is a directory"));
    EXPECT_THAT(r.err, HasSubstr("frame 3: " + path("f.0003.exr") + ": unreadable (truncated or damaged"));
    EXPECT_THAT(r.err, HasSubstr("frame 3: " + path("f.0003.exr")));
    EXPECT_THAT(r.err, ::testing::Not(HasSubstr("frame 2:")));
    EXPECT_THAT(r.err, ::testing::Not(HasSubstr("frame 1:")));

    const ProcessResult quiet = frames({"1-6", path("f.%04d.exr"), "--missing", "-q", "--paths"});
    EXPECT_EQ(quiet.exit_code, 0);
    EXPECT_EQ(quiet.err, "");
    EXPECT_THAT(quiet.out, HasSubstr(path("f.0002.exr") + "\n"));
}

TEST_F(FramesCli, MissingChecksSampleCountAndSizeWhenAsked) {
    render("f.0001.exr", {"--frame", "1", "--spp", "2"});
    render("f.0002.exr", {"--frame", "2", "--spp", "3"});
    EXPECT_EQ(frames({"1-2", path("f.%04d.exr"), "--missing"}).out, "");
    const ProcessResult spp = frames({"1-2", path("f.%04d.exr"), "--missing", "--spp", "3"});
    EXPECT_EQ(spp.out, "1\n");
    EXPECT_THAT(spp.err, HasSubstr("holds 2 of 3 spp"));
    // At least the samples asked for: a frame of 3 has the 2 asked.
    EXPECT_EQ(frames({"1-2", path("f.%04d.exr"), "--missing", "--spp", "2"}).out, "");
    const ProcessResult size = frames({"1-2", path("f.%04d.exr"), "--missing", "--width", "8", "--height", "5"});
    EXPECT_EQ(size.out, "1\n2\n");
    EXPECT_THAT(size.err, HasSubstr("rendered at 8x6, 8x5 asked"));
    EXPECT_EQ(frames({"1-2", path("f.%04d.exr"), "--missing", "--width", "8", "--height", "6"}).out, "");
}

TEST_F(FramesCli, MissingChecksTheSamplesOfASlice) {
    render("s.0001.exr", {"--frame", "1", "--sample-range", "4:3"});
    EXPECT_EQ(frames({"1", path("s.%04d.exr"), "--missing", "--samples", "4:3"}).out, "");
    EXPECT_EQ(frames({"1", path("s.%04d.exr"), "--missing", "--samples", "04:003"}).out, "");
    const ProcessResult other = frames({"1", path("s.%04d.exr"), "--missing", "--samples", "0:3"});
    EXPECT_EQ(other.out, "1\n");
    EXPECT_THAT(other.err, HasSubstr("holds the samples 4:3, 0:3 asked"));
    EXPECT_EQ(frames({"1", path("s.%04d.exr"), "--missing", "--sample-range", "4:3"}).out, "");
    // A whole render holds 0:spp.
    render("w.0001.exr", {"--frame", "1", "--spp", "3"});
    EXPECT_EQ(frames({"1", path("w.%04d.exr"), "--missing", "--samples", "0:3"}).out, "");
    for (const char* bad : {"3", "1:0", "a:2", ":2", "1:", "-1:2"}) {
        const ProcessResult r = frames({"1", path("s.%04d.exr"), "--missing", "--samples", bad});
        EXPECT_EQ(r.exit_code, 2) << bad;
        EXPECT_THAT(r.err, HasSubstr("--samples: expected START:COUNT")) << bad;
    }
}

// orb-frames --missing --scene, orb-render --missing and what orb-render
// --skip-existing really renders, with the same options, on one folder that
// holds every kind of file there can be.
TEST_F(FramesCli, MissingAgreesWithOrbRenderOnEveryKindOfFile) {
    const std::vector<std::string> asked{"--spp", "4", "--seed", "3"};
    const auto frame = [&](int number, std::vector<std::string> extra) {
        std::vector<std::string> args{"--frame", std::to_string(number)};
        args.insert(args.end(), extra.begin(), extra.end());
        render("f." + std::string(number < 10 ? "000" : "00") + std::to_string(number) + ".exr", args);
    };
    frame(1, asked);                                               // finished
    frame(2, {"--spp", "6", "--seed", "3"});                       // more samples than asked: finished
    frame(3, {"--spp", "100000", "--seed", "3", "--time", "0.000001"});  // stopped short: continued
    frame(4, {"--spp", "2", "--seed", "3"});                       // fewer samples: continued
    frame(5, {"--spp", "4", "--seed", "3", "--passes", "beauty,depth"});  // other layers
    frame(6, {"--spp", "4", "--seed", "4"});                       // other seed
    frame(7, {"--spp", "4", "--seed", "3", "--mode", "direct"});   // other light transport
    frame(8, {"--spp", "4", "--seed", "3", "--fps", "30"});        // another moment
    frame(9, {"--sample-range", "2:2", "--seed", "3"});            // a slice, not a whole frame
    frame(10, asked);                                              // cut short below
    fs::resize_file(path("f.0010.exr"), fs::file_size(path("f.0010.exr")) - 16);
    {  // rendered from another scene: the same glTF with its mirror ball moved
        std::ifstream in(kScene);
        std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        const auto at = text.find("0.9,");
        ASSERT_NE(at, std::string::npos);
        text.replace(at, 4, "0.5,");
        std::ofstream(path("moved.gltf")) << text;
        std::vector<std::string> args{ORB_RENDER_EXE, path("moved.gltf"), "--width", "8", "--height", "6", "-q",
                                      "--frame", "11", "-o", path("f.0011.exr")};
        args.insert(args.end(), asked.begin(), asked.end());
        ASSERT_EQ(run_process(args).exit_code, 0);
    }
    // 12 is absent.
    const std::string expected = "3\n4\n5\n6\n7\n8\n9\n10\n11\n12\n";

    std::vector<std::string> listing{"1-12", path("f.%04d.exr"), "--missing", "--scene", kScene, "--width", "8",
                                     "--height", "6"};
    listing.insert(listing.end(), asked.begin(), asked.end());
    const ProcessResult by_frames = frames(listing);
    EXPECT_EQ(by_frames.out, expected) << by_frames.err;

    std::vector<std::string> render_args{ORB_RENDER_EXE, kScene, "--frames", "1-12", "-o", path("f.%04d.exr"),
                                         "--width", "8", "--height", "6"};
    render_args.insert(render_args.end(), asked.begin(), asked.end());
    std::vector<std::string> missing = render_args;
    missing.push_back("--missing");
    const ProcessResult by_render = run_process(missing);
    EXPECT_EQ(by_render.out, expected) << by_render.err;
    // The same reasons, word for word.
    EXPECT_EQ(by_render.err, std::regex_replace(by_frames.err, std::regex("orb-frames: "), "orb-render: "));

    render_args.push_back("--skip-existing");
    const ProcessResult rendered = run_process(render_args);
    ASSERT_EQ(rendered.exit_code, 0) << rendered.err;
    std::string done;
    for (int f = 1; f <= 12; ++f)
        if (rendered.err.find("frame " + std::to_string(f) + ": done") != std::string::npos)
            done += std::to_string(f) + "\n";
    EXPECT_EQ(done, expected) << rendered.err;
    EXPECT_EQ(frames(listing).out, "");
    EXPECT_EQ(run_process(missing).out, "");

    // Without --scene the scene is not compared: the frame of the moved mirror ball passes.
    listing.erase(listing.begin() + 3, listing.begin() + 5);
    fs::remove(path("f.0011.exr"));
    ASSERT_EQ(run_process({ORB_RENDER_EXE, path("moved.gltf"), "--width", "8", "--height", "6", "-q", "--frame", "11",
                           "-o", path("f.0011.exr"), "--spp", "4", "--seed", "3"})
                  .exit_code,
              0);
    EXPECT_EQ(frames(listing).out, "") << frames(listing).err;
    listing.insert(listing.begin() + 3, {"--scene", kScene});
    EXPECT_EQ(frames(listing).out, "11\n");
}

TEST_F(FramesCli, AClosedStdoutEndsItAsItEndsSeq) {
    // A reader that stops early ends the listing by SIGPIPE (status 141 under
    // pipefail), with no message: what `seq 1 200000 | head -n 1` does.
    const ProcessResult r = run_process({"/bin/bash", "-c", std::string(ORB_FRAMES_EXE) + " 1-200000 | head -n 1"});
    EXPECT_EQ(r.out, "1\n");
    const ProcessResult status = run_process(
        {"/bin/bash", "-c", "set -o pipefail; " + std::string(ORB_FRAMES_EXE) + " 1-200000 | head -n 1 >/dev/null"});
    EXPECT_EQ(status.exit_code, 141) << status.err;
    EXPECT_EQ(status.err, "");
}

}  // namespace

// The camera options are part of the render orb-frames --missing compares,
// the orbit with the range of the list judged (or --orbit-frames), as
// orb-render --frames renders it.
TEST_F(FramesCli, MissingComparesTheCameraOptionsAndTheOrbit) {
    const std::vector<std::string> camera{"--orbit", "180", "--look-at", "0,0.5,0"};
    std::vector<std::string> all{ORB_RENDER_EXE, kScene, "--frames", "1-4", "--width", "8", "--height", "6", "--spp",
                                 "1", "-q", "-o", path("o.%04d.exr")};
    all.insert(all.end(), camera.begin(), camera.end());
    ASSERT_EQ(run_process(all).exit_code, 0);
    std::vector<std::string> listing{"1-4", path("o.%04d.exr"), "--missing", "--scene", kScene,
                                     "--width", "8", "--height", "6", "--spp", "1"};
    const auto judged = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = listing;
        args.insert(args.end(), extra.begin(), extra.end());
        const ProcessResult r = frames(args);
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return r.out;
    };
    EXPECT_EQ(judged(camera), "");
    // A part of the list judges its frames on the whole list's orbit only when told the whole list.
    listing[0] = "3-4";
    EXPECT_EQ(judged({"--orbit", "180", "--look-at", "0,0.5,0", "--orbit-frames", "1-4"}), "");
    EXPECT_EQ(judged(camera), "3\n4\n");  // 3-4 alone puts 3 at 0 and 4 at 90 degrees, not 90 and 135
    listing[0] = "1-4";
    EXPECT_EQ(judged({"--orbit", "180"}), "1\n2\n3\n4\n");  // the look-at differs
    EXPECT_EQ(judged({"--look-at", "0,0.5,0"}), "2\n3\n4\n");  // no orbit: only frame 1 is at 0 degrees
    // Camera options need the scene to compare.
    const ProcessResult no_scene = frames({"1-4", path("o.%04d.exr"), "--missing", "--vfov", "30"});
    EXPECT_EQ(no_scene.exit_code, 2);
    EXPECT_NE(no_scene.err.find("give --scene SCENE"), std::string::npos) << no_scene.err;
}

namespace {

// A numbered series of a styled trajectory: orb-frames --missing --scene judges each frame (frame 1
// the scene it read and styled for the plan, as orb-render does) against orb-render's outputs, and
// writes the same legend.
TEST_F(FramesCli, MissingJudgesAStyledSeriesAsOrbRenderRendersIt) {
    const char* frames_text[] = {"3\nframe 1\nO 0 0 0\nH 0.76 0.59 0\nH -0.76 0.59 0\n",
                                 "3\nframe 2\nO 0 0.3 0\nH 0.76 0.89 0\nH -0.76 0.89 0\n",
                                 "2\nframe 3\nO 0 0.6 0\nH 0.76 1.19 0\n"};
    for (int k = 0; k < 3; ++k) std::ofstream(path("water." + std::to_string(k + 1) + ".xyz")) << frames_text[k];
    const std::string series = path("water.*.xyz");
    const std::vector<std::string> style{"--radius-scale", "0.5", "--color-by", "element", "--width", "8",
                                         "--height", "6", "--spp", "1"};
    std::vector<std::string> render_args{ORB_RENDER_EXE, series, "--frames", "1-3", "-q", "--legend",
                                         path("render-legend.png"), "-o", path("w.%04d.exr")};
    render_args.insert(render_args.end(), style.begin(), style.end());
    const ProcessResult rendered = run_process(render_args);
    ASSERT_EQ(rendered.exit_code, 0) << rendered.err;

    std::vector<std::string> judged{"1-3", path("w.%04d.exr"), "--missing", "--scene", series, "--legend",
                                    path("frames-legend.png")};
    judged.insert(judged.end(), style.begin(), style.end());
    const ProcessResult finished = frames(judged);
    EXPECT_EQ(finished.exit_code, 0) << finished.err;
    EXPECT_EQ(finished.out, "");
    std::ifstream a(path("render-legend.png"), std::ios::binary), b(path("frames-legend.png"), std::ios::binary);
    const std::string legend_a{std::istreambuf_iterator<char>(a), {}}, legend_b{std::istreambuf_iterator<char>(b), {}};
    EXPECT_FALSE(legend_a.empty());
    EXPECT_EQ(legend_a, legend_b);
    // Another styling is another render of every frame, frame 1 included.
    const ProcessResult unstyled =
        frames({"1-3", path("w.%04d.exr"), "--missing", "--scene", series, "--width", "8", "--height", "6", "--spp", "1"});
    EXPECT_EQ(unstyled.exit_code, 0) << unstyled.err;
    EXPECT_EQ(unstyled.out, "1\n2\n3\n");
}

}  // namespace
