// The same command gives the same bits: whatever the machine's load and
// the pass sizes it leads to, whatever grouping of sample slices orb-merge
// adds, however a render is stopped (SIGKILL after a checkpoint included)
// and continued; every layer, the variance included (docs/orb-render.md,
// "Repeatable images"). The film's sums are integers, added exactly
// (docs/design/exact-film-sums.md).
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <memory>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"

using namespace orb::test;
using orb::exr::read_film_exr;

namespace {

namespace fs = std::filesystem;

// orb-render with an environment variable set (a development knob).
ProcessResult render_with(const std::string& variable, const std::vector<std::string>& args) {
    std::vector<std::string> argv{"/usr/bin/env", variable, render_exe()};
    argv.insert(argv.end(), args.begin(), args.end());
    return run_process(argv);
}

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

}  // namespace

TEST_F(RenderCli, PassSizesChangeNoBit) {
    const std::string scene = write_scene(small_scene());
    const std::vector<std::string> common{scene, "--spp", "24", "--seed", "4", "--passes", "all"};
    ASSERT_EQ(render(with(common, {"-o", path("timed.exr")})).exit_code, 0);
    for (const char* spp : {"1", "5", "23"}) {
        const std::string out = path(std::string("passes-of-") + spp + ".exr");
        const auto run = render_with(std::string("ORB_PASS_SPP=") + spp,
                                     with(common, {"-o", out, "--stats-json", path("stats.json")}));
        ASSERT_EQ(run.exit_code, 0) << run.err;
        // The first pass is one sample, the others as asked.
        const int passes = 1 + (23 + std::stoi(spp) - 1) / std::stoi(spp);
        EXPECT_NE(read_text(path("stats.json")).find("\"passes\": " + std::to_string(passes)), std::string::npos)
            << spp << ": " << read_text(path("stats.json"));
        SCOPED_TRACE(std::string("passes of ") + spp);
        expect_same_image(path("timed.exr"), out);
    }
}

// Busy processes on every core (ours, ended by pid) slow the passes down,
// so the pass tuner sizes them otherwise than on an idle machine.
TEST_F(RenderCli, MachineLoadChangesNoBit) {
    const std::string scene = write_scene(small_scene());
    const std::vector<std::string> common{scene, "--spp", "96", "--seed", "6", "--passes", "all", "--width", "48",
                                          "--height", "36"};
    ASSERT_EQ(render(with(common, {"-o", path("idle.exr")})).exit_code, 0);
    {
        std::vector<std::unique_ptr<Child>> load;
        const long cores = std::max(1L, ::sysconf(_SC_NPROCESSORS_ONLN));
        for (long i = 0; i < cores; ++i)
            load.push_back(std::make_unique<Child>(std::vector<std::string>{"/bin/sh", "-c", "while :; do :; done"},
                                                   path("load.txt")));
        const auto loaded = render(with(common, {"-o", path("loaded.exr")}));
        ASSERT_EQ(loaded.exit_code, 0) << loaded.err;
        for (auto& child : load) child->send_signal(SIGKILL);  // and reaped by ~Child
    }
    expect_same_image(path("idle.exr"), path("loaded.exr"));
}

TEST_F(RenderCli, SlicesMergedInAnyGroupingEqualTheWholeRender) {
    const std::string scene = write_scene(small_scene());
    const std::vector<std::string> common{scene, "--seed", "2", "--passes", "all"};
    ASSERT_EQ(render(with(common, {"--spp", "12", "-o", path("whole.exr")})).exit_code, 0);
    for (const auto& [range, name] : {std::pair{"0:3", "a.exr"}, {"3:4", "b.exr"}, {"7:5", "c.exr"}})
        ASSERT_EQ(render(with(common, {"--sample-range", range, "-o", path(name)})).exit_code, 0) << range;
    // All at once, ((a + b) + c), (a + (b + c)) and ((c + a) + b).
    ASSERT_EQ(merge({path("b.exr"), path("c.exr"), path("a.exr"), "-o", path("abc.exr")}).exit_code, 0);
    ASSERT_EQ(merge({path("a.exr"), path("b.exr"), "-o", path("ab.exr")}).exit_code, 0);
    ASSERT_EQ(merge({path("ab.exr"), path("c.exr"), "-o", path("ab_c.exr")}).exit_code, 0);
    ASSERT_EQ(merge({path("b.exr"), path("c.exr"), "-o", path("bc.exr")}).exit_code, 0);
    ASSERT_EQ(merge({path("a.exr"), path("bc.exr"), "-o", path("a_bc.exr")}).exit_code, 0);
    ASSERT_EQ(merge({path("c.exr"), path("a.exr"), "-o", path("ca.exr")}).exit_code, 0);
    const auto last = merge({path("ca.exr"), path("b.exr"), "-o", path("ca_b.exr")});
    ASSERT_EQ(last.exit_code, 0) << last.err;
    EXPECT_EQ(last.err.find("warning"), std::string::npos) << last.err;
    for (const char* merged : {"abc.exr", "ab_c.exr", "a_bc.exr", "ca_b.exr"}) {
        SCOPED_TRACE(merged);
        EXPECT_EQ(read_film_exr(path(merged)).film.sample_ranges.format(), "0:12");
        expect_same_image(path("whole.exr"), path(merged));
    }
    // Merges keep their exact sums, so any two of them are the same file's pixels, exact sums included.
    expect_same_image(path("ab_c.exr"), path("a_bc.exr"));
}

// A render killed outright (SIGKILL: nothing is written at the end) leaves
// its last checkpoint, with the exact sums, and its lock; the same command
// with --skip-existing takes the lock over, continues the checkpoint and
// ends at the uninterrupted render's bits.
TEST_F(RenderCli, ARenderKilledAfterACheckpointContinuesToTheSameBits) {
    const std::string scene = write_scene(small_scene());
    const std::string out = path("out.exr");
    const std::vector<std::string> common{scene, "--spp", "3000", "--seed", "8", "--passes", "all"};
    Child child(with({render_exe()}, with(common, {"-o", out, "--checkpoint", "0.05"})), path("killed.txt"));
    ASSERT_TRUE(eventually([&] { return fs::exists(out); }, 60)) << read_text(path("killed.txt"));
    child.send_signal(SIGKILL);
    const auto killed = child.wait(60);
    EXPECT_EQ(killed.term_signal, SIGKILL);
    const auto checkpoint = read_film_exr(out);
    ASSERT_LT(checkpoint.film.samples_per_pixel, 3000u) << "the render ended before it was killed";
    EXPECT_TRUE(checkpoint.exact);
    EXPECT_TRUE(fs::exists(path(".out.exr.lock")));

    const auto continued = render(with(common, {"-o", out, "--skip-existing"}));
    ASSERT_EQ(continued.exit_code, 0) << continued.err;
    EXPECT_NE(continued.err.find("continuing it"), std::string::npos) << continued.err;
    ASSERT_EQ(render(with(common, {"-o", path("whole.exr")})).exit_code, 0);
    expect_same_image(path("whole.exr"), out);
    // Nothing of the killed run is left: its lock and temporaries went with the run that took over.
    for (const std::string& name : files()) EXPECT_EQ(name.find(".out.exr"), std::string::npos) << name;
}

TEST_F(RenderCli, AFrameOfASequenceIsTheSameFrameRenderedAlone) {
    const std::string scene = write_scene(moving_ball_scene());
    const std::vector<std::string> common{scene, "--spp", "9", "--seed", "1", "--passes", "all"};
    ASSERT_EQ(render(with(common, {"--frames", "3-5", "-o", path("seq.####.exr")})).exit_code, 0);
    ASSERT_EQ(render_with("ORB_PASS_SPP=2", with(common, {"--frame", "4", "-o", path("alone.exr")})).exit_code, 0);
    expect_same_image(path("seq.0004.exr"), path("alone.exr"));
}

// Sums past the film's range (a light of 10^12 seen directly: its square
// alone passes it) are said, channel by channel, and never wrap around.
TEST_F(RenderCli, SumsThatPassTheFilmsRangeAreReported) {
    orb::Scene scene = small_scene();
    for (orb::Material& material : scene.materials)
        if (material.emission[0] > 0) material.emission = {1e12, 1e12, 1e12};
    const auto run = render({write_scene(scene), "--spp", "2", "--passes", "beauty,variance", "-o", path("bright.exr")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("warning: the radiance sums of "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("warning: the radiance_sq sums of "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("reached the film's range, 2^38 (2.7e11) per pixel"), std::string::npos) << run.err;
    const auto film = read_film_exr(path("bright.exr"));
    for (orb::film::Sum sum : film.film.radiance) EXPECT_GE(sum, 0);
}
