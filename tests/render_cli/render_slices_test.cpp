// One frame over many machines: orb-render --sample-range renders exactly a
// slice of the sample sequence, orb-merge sums slices, and the result is the
// render of their union bit for bit, which --resume continues.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"

using namespace orb::test;
using orb::exr::read_film_exr;

namespace {

// Two images of the same samples, one rendered whole and one summed from
// slices (merged, continued): the same bits in every layer, for the film's
// sums are integers and the slices carry them exactly.
void expect_same_render(const std::string& path_a, const std::string& path_b) {
    const auto a = read_film_exr(path_a);
    const auto b = read_film_exr(path_b);
    ASSERT_EQ(a.film.samples_per_pixel, b.film.samples_per_pixel);
    ASSERT_EQ(a.film.sample_ranges, b.film.sample_ranges);
    ASSERT_EQ(a.passes, b.passes);
    expect_same_image(path_a, path_b);
}

}  // namespace

TEST_F(RenderCli, ASampleRangeRendersExactlyThoseSamplesAndRecordsThem) {
    const std::string scene = write_scene(small_scene());
    const auto run = render({scene, "--sample-range", "16:3", "-o", path("slice.exr"), "--seed", "3"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("samples 16:3"), std::string::npos) << run.err;
    const auto slice = read_film_exr(path("slice.exr"));
    EXPECT_EQ(slice.film.samples_per_pixel, 3u);
    EXPECT_EQ(slice.film.sample_ranges.format(), "16:3");
    EXPECT_EQ(slice.metadata.target_spp, 3u);

    // The same count from sample 0 is other samples: another image.
    ASSERT_EQ(render({scene, "--spp", "3", "-o", path("first.exr"), "--seed", "3"}).exit_code, 0);
    const auto first = read_film_exr(path("first.exr"));
    EXPECT_EQ(first.film.sample_ranges.format(), "0:3");
    EXPECT_NE(first.film.radiance, slice.film.radiance);
}

TEST_F(RenderCli, MergedSlicesEqualOneRenderOfTheirUnion) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "--spp", "10", "-o", path("whole.exr"), "--seed", "9"}).exit_code, 0);
    for (const auto& [range, name] : {std::pair{"0:3", "a.exr"}, {"3:4", "b.exr"}, {"7:3", "c.exr"}})
        ASSERT_EQ(render({scene, "--sample-range", range, "-o", path(name), "--seed", "9"}).exit_code, 0) << range;

    // In any order of the arguments.
    const auto run = merge({path("c.exr"), path("a.exr"), path("b.exr"), "-o", path("merged.exr")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto merged = read_film_exr(path("merged.exr"));
    EXPECT_EQ(merged.film.samples_per_pixel, 10u);
    EXPECT_EQ(merged.film.sample_ranges.format(), "0:10");
    EXPECT_EQ(merged.metadata.target_spp, 10u);  // a finished frame: reached its target
    EXPECT_EQ(merged.metadata.seed, 9u);
    EXPECT_EQ(merged.metadata.version, ORB_VERSION);
    expect_same_render(path("whole.exr"), path("merged.exr"));
}

TEST_F(RenderCli, ResumeContinuesAMergedFile) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "--spp", "12", "-o", path("whole.exr")}).exit_code, 0);
    ASSERT_EQ(render({scene, "--sample-range", "0:4", "-o", path("a.exr")}).exit_code, 0);
    ASSERT_EQ(render({scene, "--sample-range", "4:4", "-o", path("b.exr")}).exit_code, 0);
    ASSERT_EQ(merge({path("a.exr"), path("b.exr"), "-o", path("merged.exr")}).exit_code, 0);
    const auto run = render({scene, "--resume", path("merged.exr"), "-o", path("merged.exr"), "--spp", "12"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(read_film_exr(path("merged.exr")).film.sample_ranges.format(), "0:12");
    expect_same_render(path("whole.exr"), path("merged.exr"));
}

TEST_F(RenderCli, ResumeOfAMergeWithAGapContinuesAfterItsLastSample) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "--sample-range", "0:4", "-o", path("a.exr")}).exit_code, 0);
    ASSERT_EQ(render({scene, "--sample-range", "8:4", "-o", path("b.exr")}).exit_code, 0);
    ASSERT_EQ(merge({path("a.exr"), path("b.exr"), "-o", path("gap.exr")}).exit_code, 0);
    EXPECT_EQ(read_film_exr(path("gap.exr")).film.sample_ranges.format(), "0:4,8:4");
    const auto run = render({scene, "--resume", path("gap.exr"), "-o", path("resumed.exr"), "--spp", "12"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(read_film_exr(path("resumed.exr")).film.sample_ranges.format(), "0:4,8:8");

    // The same samples, rendered as two slices and merged.
    ASSERT_EQ(render({scene, "--sample-range", "8:8", "-o", path("c.exr")}).exit_code, 0);
    ASSERT_EQ(merge({path("a.exr"), path("c.exr"), "-o", path("reference.exr")}).exit_code, 0);
    expect_same_render(path("reference.exr"), path("resumed.exr"));
}

TEST_F(RenderCli, AnInterruptedSliceResumesToItsEnd) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "--sample-range", "16:8", "-o", path("whole.exr")}).exit_code, 0);
    ASSERT_EQ(render({scene, "--sample-range", "16:3", "-o", path("part.exr")}).exit_code, 0);
    const auto wrong = render({scene, "--resume", path("part.exr"), "--sample-range", "0:8", "-o", path("x.exr")});
    EXPECT_EQ(wrong.exit_code, 1);
    EXPECT_NE(wrong.err.find("not the start of --sample-range 0:8"), std::string::npos) << wrong.err;
    const auto run =
        render({scene, "--resume", path("part.exr"), "--sample-range", "16:8", "-o", path("part.exr")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(read_film_exr(path("part.exr")).film.sample_ranges.format(), "16:8");
    expect_same_render(path("whole.exr"), path("part.exr"));
}

TEST_F(RenderCli, SampleRangeUsageErrors) {
    const std::string scene = write_scene(small_scene());
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"--sample-range", "5"}, {"--sample-range", "5:0"}, {"--sample-range", "-1:4"},
          {"--sample-range", "0:2147483648"}, {"--sample-range", "0:4", "--spp", "4"}}) {
        std::vector<std::string> argv{scene, "-o", path("out.exr")};
        argv.insert(argv.end(), args.begin(), args.end());
        const auto run = render(argv);
        EXPECT_EQ(run.exit_code, 2) << args[1] << ": " << run.err;
    }
    EXPECT_EQ(render({"--benchmark", scene, "--sample-range", "0:4"}).exit_code, 2);
    EXPECT_EQ(files(), (std::vector<std::string>{"scene.json"}));
}
