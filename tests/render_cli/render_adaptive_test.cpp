// orb-render's adaptive sampling from the command line
// (docs/orb-render.md, "Adaptive sampling"): its options' checks, what the
// output holds, and --resume, slices and orb-merge with it.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"

using namespace orb::test;
using orb::exr::read_film_exr;
using orb::exr::testing::read_raw_exr;

TEST_F(RenderCli, AdaptiveOptionsRefuseValuesThatAreNotPositiveNumbers) {
    const std::string scene = write_scene(small_scene());
    for (const char* option : {"--noise-threshold", "--target-error"})
        for (const char* value : {"0", "-0.1", "nan", "inf", "abc", "0.1x", ""}) {
            const auto run = render({scene, "-o", path("out.exr"), option, value});
            EXPECT_EQ(run.exit_code, 2) << option << " " << value << ": " << run.err;
            EXPECT_NE(run.err.find(option), std::string::npos) << run.err;
            EXPECT_FALSE(std::filesystem::exists(path("out.exr")));
        }
}

TEST_F(RenderCli, AdaptiveSamplingRefusesTheBenchmark) {
    const std::string scene = write_scene(small_scene());
    const auto bench = render({scene, "--benchmark", "--target-error", "0.01"});
    EXPECT_EQ(bench.exit_code, 2);
    EXPECT_NE(bench.err.find("takes no --benchmark"), std::string::npos) << bench.err;
}

namespace {

const std::string kBounce = std::string(ORB_SCENES_DIR) + "/bounce.gltf";

std::string frame_file(const std::string& folder, int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "/b.%04d.exr", frame);
    return folder + name;
}

}  // namespace

// --frames: each frame is an adaptive render of its own, deciding on its own
// film: the same pixels stop as in that frame rendered alone, and the file
// says it ended on its rule (orb:adaptiveStop).
TEST_F(RenderCli, EachFrameIsAnAdaptiveRenderOfItsOwn) {
    const std::vector<std::string> adaptive{"--width", "32", "--height", "24", "--spp", "4096", "--noise-threshold", "0.1"};
    auto with = [&](std::vector<std::string> args) {
        args.insert(args.end(), adaptive.begin(), adaptive.end());
        return args;
    };
    const auto run = render(with({kBounce, "--frames", "1-2", "-o", path("b.%04d.exr")}));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    ASSERT_EQ(render(with({kBounce, "--frame", "2", "-o", path("alone.exr")})).exit_code, 0);
    for (int frame = 1; frame <= 2; ++frame) {
        const auto file = read_film_exr(frame_file(path(""), frame));
        ASSERT_TRUE(file.metadata.adaptive_stop) << frame;
        EXPECT_EQ(*file.metadata.adaptive_stop, orb::exr::AdaptiveStop::Noise) << frame;
        EXPECT_LT(file.film.samples_per_pixel, 4096u) << frame;
        const auto [fewest, most] = std::minmax_element(file.film.sample_count.begin(), file.film.sample_count.end());
        EXPECT_EQ(*fewest, 16.0f) << frame;  // the sky stops at the first decision
        EXPECT_GT(*most, 16.0f) << frame;
    }
    const auto alone = read_film_exr(path("alone.exr"));
    const auto second = read_film_exr(frame_file(path(""), 2));
    EXPECT_EQ(alone.film.sample_count, second.film.sample_count);
    expect_same_image(read_raw_exr(path("alone.exr")), read_raw_exr(frame_file(path(""), 2)));
}

// --skip-existing, --claim and --missing: a frame that ended on its
// adaptive rule is finished; one with other adaptive settings is rendered
// again, saying why; one stopped short (fewer samples asked) is continued
// to the image an uninterrupted render makes.
TEST_F(RenderCli, AdaptiveFramesAreFinishedWhenTheyStoppedOnTheirRule) {
    const auto frames = [&](const std::string& spec, std::vector<std::string> extra) {
        std::vector<std::string> args{kBounce, "--frames", spec, "--width", "32", "--height", "24", "-o",
                                      path("b.%04d.exr")};
        args.insert(args.end(), extra.begin(), extra.end());
        return render(args);
    };
    const std::vector<std::string> converging{"--spp", "4096", "--noise-threshold", "0.1"};
    ASSERT_EQ(frames("1-2", converging).exit_code, 0);
    auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    const auto missing = frames("1-3", with(converging, {"--missing"}));
    ASSERT_EQ(missing.exit_code, 0) << missing.err;
    EXPECT_EQ(missing.out, "3\n");
    const auto skipping = frames("1-3", with(converging, {"--skip-existing"}));
    ASSERT_EQ(skipping.exit_code, 0) << skipping.err;
    std::size_t skipped = 0;
    for (std::size_t at = skipping.err.find("; skipped"); at != std::string::npos; at = skipping.err.find("; skipped", at + 1))
        ++skipped;
    EXPECT_EQ(skipped, 2u) << skipping.err;
    EXPECT_NE(skipping.err.find("1 rendered, 2 finished already"), std::string::npos) << skipping.err;
    const auto claiming = frames("1-3", with(converging, {"--claim"}));
    ASSERT_EQ(claiming.exit_code, 0) << claiming.err;
    EXPECT_NE(claiming.err.find("0 rendered, 3 finished already"), std::string::npos) << claiming.err;

    const auto other = frames("1-3", {"--spp", "4096", "--noise-threshold", "0.05", "--missing"});
    EXPECT_EQ(other.out, "1\n2\n3\n");
    EXPECT_NE(other.err.find("rendered with --noise-threshold 0.1, 0.05 asked"), std::string::npos) << other.err;
    const auto target = frames("1", {"--spp", "4096", "--noise-threshold", "0.1", "--target-error", "0.001", "--missing"});
    EXPECT_EQ(target.out, "1\n");
    EXPECT_NE(target.err.find("rendered with --target-error none, 0.001 asked"), std::string::npos) << target.err;

    // 40 samples of a threshold no pixel reaches by then, then 72 asked: continued.
    const std::vector<std::string> strict{"--noise-threshold", "0.001", "--seed", "4"};
    ASSERT_EQ(frames("5", with({"--spp", "40"}, strict)).exit_code, 0);
    EXPECT_FALSE(read_film_exr(frame_file(path(""), 5)).metadata.adaptive_stop);
    const auto more = frames("5", with({"--spp", "72", "--skip-existing"}, strict));
    ASSERT_EQ(more.exit_code, 0) << more.err;
    EXPECT_NE(more.err.find("holds 40 of 72 spp: continuing it"), std::string::npos) << more.err;
    ASSERT_EQ(render(with({kBounce, "--frame", "5", "--width", "32", "--height", "24", "-o", path("whole.exr"), "--spp",
                           "72"},
                          strict))
                  .exit_code,
              0);
    // Finished at 40, the frame kept its means only: continued from them
    // (said in a warning), within float rounding of the uninterrupted render.
    EXPECT_NE(more.err.find("holds means only"), std::string::npos) << more.err;
    const auto whole = read_film_exr(path("whole.exr"));
    const auto continued = read_film_exr(frame_file(path(""), 5));
    EXPECT_EQ(continued.film.sample_count, whole.film.sample_count);
    expect_same_within_float_rounding(read_raw_exr(path("whole.exr")), read_raw_exr(frame_file(path(""), 5)));
}

TEST_F(RenderCli, AnAdaptiveRenderWritesItsCountsAndSettings) {
    const std::string scene = write_scene(small_scene());
    const auto run = render({scene, "-o", path("out.exr"), "--spp", "64", "--noise-threshold", "0.05",
                             "--stats-json", path("stats.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto file = read_film_exr(path("out.exr"));
    EXPECT_EQ(orb::exr::format_passes(file.passes), "beauty,variance,samples");
    ASSERT_TRUE(file.metadata.noise_threshold);
    EXPECT_EQ(*file.metadata.noise_threshold, 0.05);
    EXPECT_FALSE(file.metadata.target_error);
    double drawn = 0, fewest = 1e9, most = 0;
    for (float count : file.film.sample_count) {
        drawn += count;
        fewest = std::min<double>(fewest, count);
        most = std::max<double>(most, count);
    }
    EXPECT_GE(fewest, 16.0);  // no pixel stops before the first decision
    EXPECT_LE(most, 64.0);
    EXPECT_LT(fewest, most);
    std::ifstream stats(path("stats.json"));
    const std::string text((std::istreambuf_iterator<char>(stats)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("\"samples\": " + std::to_string(static_cast<long long>(drawn))), std::string::npos) << text;
    EXPECT_NE(text.find("\"estimated_relmse\""), std::string::npos) << text;
}

TEST_F(RenderCli, AnAdaptiveRenderResumesToTheUninterruptedImage) {
    const std::string scene = write_scene(small_scene());
    const std::vector<std::string> adaptive{"--noise-threshold", "0.05", "--seed", "3"};
    auto with = [&](std::vector<std::string> args) {
        args.insert(args.end(), adaptive.begin(), adaptive.end());
        return args;
    };
    ASSERT_EQ(render(with({scene, "-o", path("whole.exr"), "--spp", "72"})).exit_code, 0);
    // Stopped by --time after its first pass: its exact sums go on.
    ASSERT_EQ(render(with({scene, "-o", path("part.exr"), "--spp", "72", "--time", "0.000001"})).exit_code, 0);
    // The threshold comes from the file's orb:noiseThreshold.
    const auto resumed = render({scene, "--resume", path("part.exr"), "-o", path("resumed.exr"), "--spp", "72"});
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    const auto whole = read_film_exr(path("whole.exr"));
    const auto again = read_film_exr(path("resumed.exr"));
    EXPECT_EQ(again.film.sample_count, whole.film.sample_count);
    expect_same_image(read_raw_exr(path("whole.exr")), read_raw_exr(path("resumed.exr")));
}

TEST_F(RenderCli, AdaptiveSlicesMergeByAddingTheirCounts) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "--sample-range", "0:48", "-o", path("a.exr"), "--noise-threshold", "0.05"}).exit_code, 0);
    ASSERT_EQ(render({scene, "--sample-range", "48:48", "-o", path("b.exr"), "--noise-threshold", "0.05"}).exit_code, 0);
    const auto run = merge({path("a.exr"), path("b.exr"), "-o", path("merged.exr")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto a = read_film_exr(path("a.exr"));
    const auto b = read_film_exr(path("b.exr"));
    const auto merged = read_film_exr(path("merged.exr"));
    EXPECT_EQ(merged.film.sample_ranges.format(), "0:96");
    ASSERT_EQ(merged.film.sample_count.size(), a.film.sample_count.size());
    for (std::size_t i = 0; i < merged.film.sample_count.size(); ++i) {
        ASSERT_EQ(merged.film.sample_count[i], a.film.sample_count[i] + b.film.sample_count[i]) << "pixel " << i;
        // Each pixel's mean is over its own count: the slices' sums added exactly, over the counts added.
        ASSERT_EQ(merged.film.radiance[i * 3], a.film.radiance[i * 3] + b.film.radiance[i * 3]) << "pixel " << i;
    }
    // A slice rendered without adaptive sampling is another render (its layers differ).
    ASSERT_EQ(render({scene, "--sample-range", "96:8", "-o", path("c.exr")}).exit_code, 0);
    const auto mixed = merge({path("a.exr"), path("c.exr"), "-o", path("mixed.exr")});
    EXPECT_EQ(mixed.exit_code, 1);
    EXPECT_NE(mixed.err.find("orb:passes"), std::string::npos) << mixed.err;
    EXPECT_FALSE(std::filesystem::exists(path("mixed.exr")));
}

TEST_F(RenderCli, TheTargetErrorStopsTheRender) {
    const std::string scene = write_scene(small_scene());
    const auto run = render({scene, "-o", path("out.exr"), "--spp", "100000", "--target-error", "0.02",
                             "--stats-json", path("stats.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("--target-error reached"), std::string::npos) << run.err;
    const auto file = read_film_exr(path("out.exr"));
    EXPECT_LT(file.film.samples_per_pixel, 100000u);
    EXPECT_EQ(orb::exr::format_passes(file.passes), "beauty,variance");  // no counts: every pixel sampled alike
    std::ifstream stats(path("stats.json"));
    const std::string text((std::istreambuf_iterator<char>(stats)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("\"stop_reason\": \"error\""), std::string::npos) << text;
}
