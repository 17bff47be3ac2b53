// orb-render's adaptive sampling from the command line
// (docs/orb-render.md, "Adaptive sampling"): its options' checks, what the
// output holds, and --resume, slices and orb-merge with it.
#include <algorithm>
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

TEST_F(RenderCli, AdaptiveSamplingRefusesFramesAndTheBenchmark) {
    const std::string scene = write_scene(small_scene());
    const auto frames = render({scene, "-o", path("f.%04d.exr"), "--frames", "1-2", "--noise-threshold", "0.1"});
    EXPECT_EQ(frames.exit_code, 2);
    EXPECT_NE(frames.err.find("adaptive sampling (--noise-threshold, --target-error) renders one image and takes no "
                              "--frame/--frames"),
              std::string::npos)
        << frames.err;
    const auto bench = render({scene, "--benchmark", "--target-error", "0.01"});
    EXPECT_EQ(bench.exit_code, 2);
    EXPECT_NE(bench.err.find("takes no --benchmark"), std::string::npos) << bench.err;
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
    ASSERT_EQ(render(with({scene, "-o", path("part.exr"), "--spp", "40"})).exit_code, 0);
    // The threshold comes from the file's orb:noiseThreshold.
    const auto resumed = render({scene, "--resume", path("part.exr"), "-o", path("resumed.exr"), "--spp", "72"});
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    const auto whole = read_film_exr(path("whole.exr"));
    const auto again = read_film_exr(path("resumed.exr"));
    EXPECT_EQ(again.film.sample_count, whole.film.sample_count);
    expect_same_within_float_rounding(read_raw_exr(path("whole.exr")), read_raw_exr(path("resumed.exr")));
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
        // Each pixel's mean is over its own count: the slices' sums added, over the counts added.
        const double expected =
            (static_cast<double>(a.film.radiance[i * 3]) + b.film.radiance[i * 3]) / merged.film.sample_count[i];
        EXPECT_NEAR(merged.film.radiance[i * 3] / merged.film.sample_count[i], expected, 1e-5 * (expected + 1e-3));
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
