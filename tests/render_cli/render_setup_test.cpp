// Options that shape the set-up rather than the image: --time-at (animated
// scenes), --kernel-dir/--no-cache, and running without any OpenCL platform.
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"
#include "orb/scene/animation.h"
#include "orb/scene/scene_json.h"

using namespace orb::test;
using orb::exr::testing::read_raw_exr;

namespace {

// small_scene() with the red ball sliding from x = -1.4 at t = 0 to x = -0.1 at t = 2.
orb::Scene animated_scene() {
    orb::Scene scene = small_scene();
    orb::AnimationNode node;
    node.name = "slider";
    orb::AnimationChannel channel;
    channel.path = orb::AnimationPath::Translation;
    channel.times = {0.0, 2.0};
    channel.values = {{-1.4, 0.7, 0.0, 0.0}, {-0.1, 0.7, 0.0, 0.0}};
    node.channels.push_back(channel);
    scene.animation.nodes.push_back(node);
    orb::SphereBinding binding;
    binding.sphere = 1;
    binding.node = 0;
    binding.radius = 0.5;
    scene.animation.spheres.push_back(binding);
    return scene;
}

std::string quoted(const std::string& text) { return "'" + text + "'"; }

std::size_t occurrences(const std::string& text, const std::string& word) {
    std::size_t count = 0;
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++count;
    return count;
}

}  // namespace

// The first render of a new kind of scene builds the kernels from source,
// seconds of silence on a CPU: it says so once when the build (the compiler
// and the kernel's first launch, where PoCL generates its code) lasts a
// second or more, as its kernel_build_seconds in --stats-json tell, and
// never otherwise; a render that loads them from the binary cache says
// nothing of it and counts no build.
TEST_F(RenderCli, BuildingKernelsFromSourceIsSaidOnceAndACachedLoadIsNot) {
    const std::string scene = write_scene(small_scene());
    const std::string message = "orb-render: building kernels for this scene (once; cached)\n";
    const auto with_cache = [&](const std::string& name) {
        return run_process({"/usr/bin/env", "XDG_CACHE_HOME=" + path("cache"), render_exe(), scene, "--width", "8",
                            "--height", "6", "--spp", "1", "-o", path(name + ".exr"), "--stats-json",
                            path(name + ".json")});
    };
    const auto build_seconds = [&](const std::string& name) {
        return nlohmann::json::parse(read_text(path(name + ".json"))).at("kernel_build_seconds").get<double>();
    };
    const auto first = with_cache("first");  // an empty cache: built from source
    ASSERT_EQ(first.exit_code, 0) << first.err;
    const double built = build_seconds("first");
    EXPECT_GT(built, 0.0);
    EXPECT_EQ(occurrences(first.err, message), built >= 1.0 ? 1u : 0u) << "built in " << built << " s\n" << first.err;
    EXPECT_EQ(occurrences(first.err, "building kernels"), occurrences(first.err, message)) << first.err;

    const auto cached = with_cache("cached");
    ASSERT_EQ(cached.exit_code, 0) << cached.err;
    EXPECT_EQ(cached.err.find("building kernels"), std::string::npos) << cached.err;
    EXPECT_EQ(build_seconds("cached"), 0.0);
}

// startup_seconds: from the process's start (as the kernel records it, to
// 10 ms) to its first pass, so it holds the set-up and lies within the
// process's wall time as the test sees it.
TEST_F(RenderCli, StartupSecondsSpanTheProcessStartToTheFirstPass) {
    const std::string scene = write_scene(small_scene());
    const auto launched = std::chrono::steady_clock::now();
    const auto run = render({scene, "--width", "8", "--height", "6", "--spp", "2", "-o", path("out.exr"),
                             "--stats-json", path("stats.json")});
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - launched).count();
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto stats = nlohmann::json::parse(read_text(path("stats.json")));
    const double startup = stats.at("startup_seconds").get<double>();
    const double tick = 1.0 / static_cast<double>(::sysconf(_SC_CLK_TCK));
    EXPECT_GE(startup + tick, stats.at("setup_seconds").get<double>());
    EXPECT_LE(startup, wall + tick);
}

TEST_F(RenderCli, TimeAtRendersTheSceneAsItStandsThen) {
    const orb::Scene scene = animated_scene();
    const std::string file = write_scene(scene);
    for (double t : {0.0, 2.0}) {
        const std::string out = path("t" + std::to_string(int(t)) + ".exr");
        const auto run = render({file, "-o", out, "--spp", "1", "--passes", "id", "--time-at", std::to_string(t)});
        ASSERT_EQ(run.exit_code, 0) << run.err;
        const orb::Scene posed = orb::scene_at_time(scene, t);
        const auto film = orb::exr::read_film_exr(out);
        EXPECT_EQ(film.metadata.scene_time, t);
        EXPECT_EQ(film.metadata.scene_hash, orb::scene_content_hash(posed));

        // The ball is found where the pose at t puts it.
        Imf::InputFile exr(out.c_str());
        const auto& c = posed.spheres[1].center;
        Imath::V3f ndc;
        Imf::worldToNDC(exr.header())
            .multVecMatrix(Imath::V3f{static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])},
                           ndc);
        const auto raw = read_raw_exr(out);
        const int x = int(ndc.x * raw.width), y = int(ndc.y * raw.height);
        ASSERT_TRUE(x >= 0 && x < raw.width && y >= 0 && y < raw.height);
        EXPECT_EQ(raw.channels.at("id")[std::size_t(y) * raw.width + x], 1.0f) << "t = " << t;
    }
    EXPECT_NE(orb::exr::read_film_exr(path("t0.exr")).metadata.scene_hash,
              orb::exr::read_film_exr(path("t2.exr")).metadata.scene_hash);
    // Resuming must stay at the file's time.
    const auto clash = render({file, "--resume", path("t2.exr"), "-o", path("r.exr"), "--spp", "2", "--time-at", "1"});
    EXPECT_EQ(clash.exit_code, 1);
    EXPECT_NE(clash.err.find("--time-at"), std::string::npos) << clash.err;
}

TEST_F(RenderCli, KernelDirIsUsedAndABuildFailurePrintsTheLog) {
    // A copy of the build's share/orb/kernels, laid out as an installed tree's.
    std::filesystem::copy(ORB_KERNELS_DIR, path("kernels"), std::filesystem::copy_options::recursive);
    const std::string scene = write_scene(small_scene());
    const auto good = render({scene, "-o", path("ok.exr"), "--spp", "1", "--kernel-dir", path("kernels"), "--no-cache"});
    ASSERT_EQ(good.exit_code, 0) << good.err;

    std::ofstream(path("kernels/integrator.cl"), std::ios::app) << "\nthis_is_not_opencl_c\n";
    const auto bad = render({scene, "-o", path("bad.exr"), "--spp", "1", "--kernel-dir", path("kernels"), "--no-cache"});
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.err.find("build log"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find("integrator.cl"), std::string::npos) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(path("bad.exr")));
}

TEST_F(RenderCli, NoOpenCLPlatformSaysToInstallPocl) {
    std::filesystem::create_directories(path("no-icds"));
    // The ICD loader reads its vendor list from OCL_ICD_VENDORS: an empty folder means no platform.
    for (const std::string& args : {std::string("--list-devices"), quoted(write_scene(small_scene())) + " -o " + quoted(path("out.exr"))}) {
        const auto run = run_process({"/bin/sh", "-c", "OCL_ICD_VENDORS=" + quoted(path("no-icds")) + " " +
                                                           quoted(render_exe()) + " " + args});
        EXPECT_EQ(run.exit_code, 1) << args << "\n" << run.err;
        EXPECT_NE(run.err.find("pocl-opencl-icd"), std::string::npos) << run.err;
    }
    EXPECT_FALSE(std::filesystem::exists(path("out.exr")));
}

// The development knobs (docs/rendering.md): a malformed one stops orb-render
// before it reads or writes anything, naming the variable and what it
// expects; a good one is used, and a moved one is named in a warning.
TEST_F(RenderCli, DevelopmentKnobsAreCheckedAtTheStart) {
    const std::string scene = write_scene(small_scene());
    const std::string out = path("knob.exr");
    const auto with_env = [&](const std::string& assignment) {
        return run_process({"/usr/bin/env", assignment, render_exe(), scene, "-o", out, "--spp", "1", "--width", "16",
                            "--height", "8"});
    };
    for (const auto& [assignment, expected] :
         {std::pair<std::string, std::string>{"ORB_LOCAL_SIZE=abc", "ORB_LOCAL_SIZE='abc': expected a work-group shape XxY"},
          {"ORB_SIMD_LANES=3", "ORB_SIMD_LANES='3': expected 0 (one path per work-item), 4, 8 or 16"},
          {"ORB_REFIT_COST_LIMIT=much", "ORB_REFIT_COST_LIMIT='much': expected a finite number"},
          {"ORB_SHOW_BUILD_LOG=yes", "ORB_SHOW_BUILD_LOG='yes': expected 1 (on) or 0 (off)"}}) {
        const auto run = with_env(assignment);
        EXPECT_EQ(run.exit_code, 2) << assignment << "\n" << run.err;
        EXPECT_NE(run.err.find("orb-render: error: development knob " + expected), std::string::npos) << run.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << assignment;
    }

    const auto good = with_env("ORB_LOCAL_SIZE=4x2");
    EXPECT_EQ(good.exit_code, 0) << good.err;
    EXPECT_TRUE(std::filesystem::exists(out));
    std::filesystem::remove(out);

    const auto moved = with_env("ORB_CAPTURE_PASS=" + path("capture"));
    EXPECT_EQ(moved.exit_code, 0) << moved.err;
    EXPECT_NE(moved.err.find("orb-render: warning: ORB_CAPTURE_PASS is set but ignored"), std::string::npos)
        << moved.err;
    EXPECT_FALSE(std::filesystem::exists(path("capture")));
}
