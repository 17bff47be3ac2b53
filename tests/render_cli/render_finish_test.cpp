// What --skip-existing (and --claim, and --missing) make of the outputs that
// are already there, on the repository's glTF animation: a finished frame is
// exactly the render asked for; the same render stopped short is continued
// from its samples to the image an uninterrupted render makes; anything else
// is rendered again, with one line saying why.
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"

using namespace orb::test;
using orb::exr::read_film_exr;
using orb::exr::testing::read_raw_exr;
namespace fs = std::filesystem;

namespace {

const std::string kBounce = std::string(ORB_SCENES_DIR) + "/bounce.gltf";

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

std::string frame_file(const std::string& folder, int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "/b.%04d.exr", frame);
    return folder + name;
}

// The lines of `text` that contain `what`.
int count_lines(const std::string& text, const std::string& what) {
    std::istringstream in(text);
    int n = 0;
    for (std::string line; std::getline(in, line);) n += line.find(what) != std::string::npos;
    return n;
}

class RenderFinish : public RenderCli {
protected:
    void SetUp() override {
        RenderCli::SetUp();
        fs::create_directories(path("shots"));
        fs::create_directories(path("reference"));
    }
    // bounce.gltf at 32x24, frames `frames`, into shots/ unless told otherwise.
    ProcessResult frames(const std::string& frames, const std::vector<std::string>& extra,
                         const std::string& folder = "shots") const {
        return render(with({kBounce, "--frames", frames, "--width", "32", "--height", "24", "-o",
                            path(folder + "/b.%04d.exr")},
                           extra));
    }
};

}  // namespace

TEST_F(RenderFinish, APreviewThenAFinalRenderInTheSameFolder) {
    // A preview at a quarter of the size and few samples.
    ASSERT_EQ(render({kBounce, "--frames", "1-3", "--width", "16", "--height", "12", "--spp", "2", "-o",
                      path("shots/b.%04d.exr")})
                  .exit_code,
              0);
    const auto final_run = frames("1-3", {"--spp", "6", "--skip-existing"});
    ASSERT_EQ(final_run.exit_code, 0) << final_run.err;
    EXPECT_EQ(count_lines(final_run.err, ": rendered at 16x12, 32x24 asked: rendering again"), 3) << final_run.err;
    for (int frame = 1; frame <= 3; ++frame) {
        const auto file = read_film_exr(frame_file(path("shots"), frame));
        EXPECT_EQ(file.film.width, 32);
        EXPECT_EQ(file.film.sample_ranges.format(), "0:6");
    }

    // A preview at the final size with fewer samples is the start of the
    // final render: continued. Finished, the preview kept its means only
    // (no exact sums), so the final image is the uninterrupted one within
    // float rounding, and a warning says so.
    ASSERT_EQ(frames("4-5", {"--spp", "2"}).exit_code, 0);
    const auto more = frames("4-5", {"--spp", "6", "--skip-existing"});
    ASSERT_EQ(more.exit_code, 0) << more.err;
    EXPECT_EQ(count_lines(more.err, ": holds 2 of 6 spp: continuing it"), 2) << more.err;
    EXPECT_EQ(count_lines(more.err, ": holds means only, no exact sums"), 2) << more.err;
    ASSERT_EQ(frames("4-5", {"--spp", "6"}, "reference").exit_code, 0);
    for (int frame = 4; frame <= 5; ++frame)
        expect_same_within_float_rounding(read_raw_exr(frame_file(path("shots"), frame)),
                                          read_raw_exr(frame_file(path("reference"), frame)));

    // Other layers, seed, mode or sampler: rendered again, each saying why.
    const struct {
        std::vector<std::string> options;
        std::string why;
    } changes[] = {{{"--passes", "beauty,albedo"}, "holds the layers 'beauty', 'beauty,albedo' asked"},
                   {{"--seed", "9"}, "rendered with another seed (orb:seed "},
                   {{"--mode", "direct"}, "rendered with --mode global, direct asked"},
                   {{"--sampler", "independent"}, "rendered with --sampler sobol, independent asked"},
                   {{"--max-depth", "3"}, "rendered with --max-depth 6, 3 asked"},
                   {{"--fps", "30"}, "rendered at scene time 0.0416667 s, 0.0333333 s asked"},
                   {{"--half"}, "stored as FLOAT, HALF (--half) asked"}};
    for (const auto& change : changes) {
        ASSERT_EQ(frames("1", {"--spp", "2"}).exit_code, 0);
        const auto run = frames("1", with({"--spp", "2", "--skip-existing"}, change.options));
        ASSERT_EQ(run.exit_code, 0) << run.err;
        EXPECT_EQ(count_lines(run.err, change.why), 1) << change.options.front() << "\n" << run.err;
        EXPECT_EQ(count_lines(run.err, ": rendering again"), 1) << run.err;
    }
}

TEST_F(RenderFinish, AnotherSceneOrCameraIsRenderedAgain) {
    std::ifstream in(kBounce);
    const nlohmann::json original = nlohmann::json::parse(in);
    const std::string scene = path("bounce.gltf");
    const auto render_edited = [&](const std::function<void(nlohmann::json&)>& edit, bool skip) {
        nlohmann::json gltf = original;
        edit(gltf);
        std::ofstream(scene) << gltf.dump();
        std::vector<std::string> args{scene, "--frames", "1", "--width", "16", "--height", "12", "--spp", "1", "-o",
                                      path("shots/b.%04d.exr")};
        if (skip) args.push_back("--skip-existing");
        return render(args);
    };
    const auto nothing = [](nlohmann::json&) {};
    ASSERT_EQ(render_edited(nothing, false).exit_code, 0);
    EXPECT_EQ(count_lines(render_edited(nothing, true).err, "finished (1 spp); skipped"), 1);

    // The mirror ball moved: the same camera, another scene.
    const auto moved = render_edited([](nlohmann::json& g) { g["nodes"][2]["translation"][0] = 0.5; }, true);
    EXPECT_EQ(count_lines(moved.err, ": rendered from another scene (orb:sceneHash "), 1) << moved.err;
    // The camera moved.
    const auto aimed = render_edited([](nlohmann::json& g) { g["nodes"][4]["translation"][1] = 2.0; }, true);
    EXPECT_EQ(count_lines(aimed.err, ": rendered from another camera"), 1) << aimed.err;

    // Only the projection changed: the same node, an orthographic camera (its worldToNDC tells them apart).
    const auto orthographic = [](nlohmann::json& g) {
        g["cameras"][0] = {{"name", "Camera"},
                           {"type", "orthographic"},
                           {"orthographic", {{"xmag", 2.4}, {"ymag", 1.8}, {"znear", 0.1}, {"zfar", 100}}}};
    };
    const auto flattened = render_edited(orthographic, true);
    EXPECT_EQ(count_lines(flattened.err, ": rendered from another camera (perspective, an orthographic one asked): "
                                         "rendering again"),
              1)
        << flattened.err;
    EXPECT_TRUE(orb::exr::is_orthographic(read_film_exr(frame_file(path("shots"), 1)).metadata.world_to_ndc));
    EXPECT_EQ(count_lines(render_edited(orthographic, true).err, "finished (1 spp); skipped"), 1);
    const auto back = render_edited(nothing, true);
    EXPECT_EQ(count_lines(back.err, ": rendered from another camera (orthographic, a perspective one asked)"), 1)
        << back.err;
}

TEST_F(RenderFinish, FramesStoppedByTimeOrSigtermAreContinuedToTheUninterruptedImage) {
    const auto bounce = [&](const std::string& frames, const std::string& folder, std::vector<std::string> extra) {
        return with({kBounce, "--frames", frames, "--width", "64", "--height", "48", "--seed", "5", "-o",
                     path(folder + "/b.%04d.exr")},
                    extra);
    };
    // A target no run reaches, so the signal lands while frame 1 renders:
    // right after its first checkpoint, a pass or two in.
    Child child(with({render_exe()}, bounce("1-2", "shots", {"--spp", "100000000", "--checkpoint", "0.05"})),
                path("stopped.txt"));
    ASSERT_TRUE(eventually([&] { return fs::exists(path("shots/b.0001.exr")); }, 60)) << read_text(path("stopped.txt"));
    child.send_signal(SIGTERM);
    const auto stopped = child.wait(60);
    ASSERT_EQ(stopped.exit_code, 143) << stopped.err;
    const std::uint64_t held = read_film_exr(path("shots/b.0001.exr")).film.samples_per_pixel;
    ASSERT_LT(held, 1000u) << "the signal came late; the frame holds " << held << " spp";
    EXPECT_FALSE(fs::exists(path("shots/b.0002.exr")));
    // Frame 3 stops at its time limit instead: after its first pass.
    ASSERT_EQ(render(bounce("3", "shots", {"--spp", "1000", "--time", "0.000001"})).exit_code, 0);
    ASSERT_LT(read_film_exr(path("shots/b.0003.exr")).film.samples_per_pixel, 1000u);

    // The samples a file holds are the first of any render of these settings,
    // whatever target it was heading for: both are continued to 1000.
    const auto continued = render(bounce("1-3", "shots", {"--spp", "1000", "--skip-existing"}));
    ASSERT_EQ(continued.exit_code, 0) << continued.err;
    EXPECT_EQ(count_lines(continued.err, "frame 1: " + path("shots/b.0001.exr") + ": holds " + std::to_string(held) +
                                             " of 1000 spp: continuing it"),
              1)
        << continued.err;
    EXPECT_EQ(count_lines(continued.err, "frame 3: " + path("shots/b.0003.exr") + ": holds "), 1) << continued.err;
    EXPECT_EQ(count_lines(continued.err, "frames: 3 rendered (2 continued), 0 finished already"), 1) << continued.err;
    ASSERT_EQ(render(bounce("1-3", "reference", {"--spp", "1000"})).exit_code, 0);
    for (int frame = 1; frame <= 3; ++frame) {
        const auto file = read_film_exr(frame_file(path("shots"), frame));
        EXPECT_EQ(file.film.sample_ranges.format(), "0:1000") << frame;
        expect_same_image(read_raw_exr(frame_file(path("shots"), frame)),
                          read_raw_exr(frame_file(path("reference"), frame)));
    }
}

TEST_F(RenderFinish, ASliceIsContinuedOnlyToItsOwnSamples) {
    ASSERT_EQ(frames("1", {"--sample-range", "4:400", "--time", "0.000001"}).exit_code, 0);
    const auto held = read_film_exr(path("shots/b.0001.exr")).film.sample_ranges;
    ASSERT_EQ(held.first(), 4u);
    ASSERT_LT(held.total(), 400u);
    const auto run = frames("1", {"--sample-range", "4:400", "--skip-existing"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(count_lines(run.err, "of 4:400: continuing it"), 1) << run.err;
    EXPECT_EQ(read_film_exr(path("shots/b.0001.exr")).film.sample_ranges.format(), "4:400");
    ASSERT_EQ(frames("1", {"--sample-range", "4:400"}, "reference").exit_code, 0);
    expect_same_image(read_raw_exr(path("shots/b.0001.exr")), read_raw_exr(path("reference/b.0001.exr")));

    // Another slice of the same frame is not this one: rendered again.
    const auto other = frames("1", {"--sample-range", "0:4", "--skip-existing"});
    EXPECT_EQ(count_lines(other.err, "holds the samples 4:400, 0:4 asked: rendering again"), 1) << other.err;
    // A whole frame of 4 samples holds 0:4: the slice 0:4 is finished.
    const auto same = frames("1", {"--sample-range", "0:4", "--skip-existing"});
    EXPECT_EQ(count_lines(same.err, "finished (4 spp); skipped"), 1) << same.err;
}

TEST_F(RenderFinish, MissingListsWhatSkipExistingRendersAndRendersNothing) {
    ASSERT_EQ(frames("1-2", {"--spp", "4"}).exit_code, 0);
    ASSERT_EQ(render({kBounce, "--frame", "3", "--width", "16", "--height", "24", "--spp", "4", "-o",
                      path("shots/b.%04d.exr")})
                  .exit_code,
              0);
    ASSERT_EQ(frames("4", {"--spp", "2"}).exit_code, 0);
    std::ofstream(path("shots/b.0005.exr")) << "not an EXR";
    const auto before = fs::last_write_time(path("shots/b.0004.exr"));
    const auto missing = frames("1-6", {"--spp", "4", "--missing"});
    ASSERT_EQ(missing.exit_code, 0) << missing.err;
    EXPECT_EQ(missing.out, "3\n4\n5\n6\n");
    EXPECT_EQ(count_lines(missing.err, "frame 3: " + path("shots/b.0003.exr") + ": rendered at 16x24, 32x24 asked"), 1)
        << missing.err;
    EXPECT_EQ(count_lines(missing.err, "frame 4: " + path("shots/b.0004.exr") + ": holds 2 of 4 spp"), 1) << missing.err;
    EXPECT_EQ(count_lines(missing.err, "frame 5: " + path("shots/b.0005.exr") + ": unreadable"), 1) << missing.err;
    EXPECT_EQ(missing.err.find("frame 6"), std::string::npos) << missing.err;  // absent: no note
    EXPECT_EQ(missing.err.find("device"), std::string::npos) << missing.err;   // no OpenCL
    EXPECT_EQ(fs::last_write_time(path("shots/b.0004.exr")), before);

    const auto rendered = frames("1-6", {"--spp", "4", "--skip-existing"});
    ASSERT_EQ(rendered.exit_code, 0) << rendered.err;
    std::set<int> done;
    for (int frame = 1; frame <= 6; ++frame)
        if (count_lines(rendered.err, "frame " + std::to_string(frame) + ": done")) done.insert(frame);
    EXPECT_EQ(done, (std::set<int>{3, 4, 5, 6})) << rendered.err;
    EXPECT_EQ(frames("1-6", {"--spp", "4", "--missing"}).out, "");

    // Usage: --missing writes nothing, so it takes no -o - and no --resume.
    EXPECT_EQ(render({kBounce, "--frame", "1", "-o", "-", "--missing"}).exit_code, 2);
    EXPECT_EQ(frames("1", {"--missing", "--claim"}).exit_code, 2);
}

// A run killed while writing a frame leaves that frame's lock; a later
// --skip-existing run that finds the frame finished (and so never takes the
// lock) removes it when its holder is gone from this host, and leaves the
// locks of live processes and of other hosts alone.
TEST_F(RenderFinish, StaleLocksOfFinishedFramesAreRemoved) {
    ASSERT_EQ(frames("1-3", {"--spp", "2"}).exit_code, 0);
    char host[256] = {};
    ASSERT_EQ(::gethostname(host, sizeof host - 1), 0);
    // A pid that no longer exists: a child of ours, run and reaped.
    const auto gone = run_process({"/bin/sh", "-c", "echo $$"});
    const std::string dead_pid = gone.out.substr(0, gone.out.find('\n'));
    const auto write_lock = [&](int frame, const std::string& holder) {
        std::ofstream(path("shots/.b.000" + std::to_string(frame) + ".exr.lock")) << holder << "\n";
    };
    write_lock(1, dead_pid + " " + host);                                  // a killed run of this host
    write_lock(2, std::to_string(::getpid()) + " " + host);                // a live process (this test)
    write_lock(3, dead_pid + " another-host-" + std::string(host));        // another host's
    const auto run = frames("1-3", {"--spp", "2", "--skip-existing"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(count_lines(run.err, "; skipped"), 3) << run.err;
    EXPECT_FALSE(fs::exists(path("shots/.b.0001.exr.lock")));
    EXPECT_TRUE(fs::exists(path("shots/.b.0002.exr.lock")));
    EXPECT_TRUE(fs::exists(path("shots/.b.0003.exr.lock")));
}

// The lock names its holder, pid and host: what the message of a second
// writer says, and what tells a stale lock.
TEST_F(RenderFinish, ALockNamesItsProcessAndHost) {
    Child child(with({render_exe()}, {kBounce, "--frames", "1", "--width", "32", "--height", "24", "--spp", "100000000",
                                      "-o", path("shots/b.%04d.exr")}),
                path("running.txt"));
    ASSERT_TRUE(eventually([&] { return fs::exists(path("shots/.b.0001.exr.lock")); }, 60))
        << read_text(path("running.txt"));
    char host[256] = {};
    ASSERT_EQ(::gethostname(host, sizeof host - 1), 0);
    EXPECT_TRUE(eventually([&] { return read_text(path("shots/.b.0001.exr.lock")).find(host) != std::string::npos; }, 10))
        << read_text(path("shots/.b.0001.exr.lock"));
    const auto second = frames("1", {"--spp", "2"});
    EXPECT_EQ(second.exit_code, 1);
    EXPECT_NE(second.err.find(" on " + std::string(host) + ") is writing this output"), std::string::npos) << second.err;
    child.send_signal(SIGKILL);
    child.wait(60);
}
