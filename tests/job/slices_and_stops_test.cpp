// Samples split among runs add up to the uninterrupted render, bit for bit:
// slices of a sample range merged, and a render stopped by its cancel flag
// then continued from its file.
#include <gtest/gtest.h>

#include "job_test_support.h"
#include "orb/exr/film_exr.h"
#include "orb/exr/film_merge.h"

namespace orb::job::test {
namespace {

using SlicesAndStops = JobTest;

TEST_F(SlicesAndStops, SlicesOfASampleRangeMergeToTheWholeRender) {
    const Scene scene = orb::test::small_scene();
    RenderPlan whole = plan(scene, still_options(scene, 8, 6, 4, 11));
    const FilmOutcome reference = run(whole);

    std::vector<exr::MergeInput> slices;
    for (const SampleRange range : {SampleRange{0, 1}, SampleRange{1, 3}}) {
        PlanOptions options = still_options(scene, 8, 6, 4, 11);
        options.given.sample_range = range;
        options.settings = resolve_settings(options.given, &scene.render);
        RenderPlan slice = plan(scene, options);
        EXPECT_TRUE(slice.slice);
        EXPECT_EQ(slice.first_sample, range.first);
        EXPECT_EQ(slice.target_spp, range.count);
        FilmOutcome part = run(slice);
        EXPECT_EQ(part.stats.sample_ranges, SampleRanges(range).format());
        const std::string file = save(part, "slice" + std::to_string(range.first) + ".exr");
        slices.push_back({file, exr::read_film_exr(file)});
    }
    const exr::ExrFilm merged = exr::merge_films(std::move(slices));
    EXPECT_TRUE(merged.exact);
    expect_same_film(merged.film, exr::read_film_exr(save(const_cast<FilmOutcome&>(reference), "whole.exr")).film);
}

TEST_F(SlicesAndStops, AStoppedRenderContinuedEqualsTheUninterruptedOne) {
    const Scene scene = orb::test::small_scene();
    RenderPlan whole = plan(scene, still_options(scene, 8, 6, 5, 21));
    const FilmOutcome reference = run(whole);
    ASSERT_EQ(reference.reason, render::StopReason::ReachedSpp);

    RenderPlan first = plan(scene, still_options(scene, 8, 6, 5, 21));
    FilmOutcome stopped = run(first, 2);  // the cancel flag, set after the second pass
    EXPECT_EQ(stopped.reason, render::StopReason::Interrupted);
    EXPECT_EQ(stopped.stats.spp, 2u);
    EXPECT_TRUE(stopped.image.options.exact_sums);  // a film stopped short keeps its exact sums
    PlanOptions resume;
    resume.resume = save(stopped, "stopped.exr");
    RenderPlan rest = plan(scene, resume);
    ASSERT_TRUE(rest.resumed.has_value());
    EXPECT_TRUE(rest.resumed->exact);
    const FilmOutcome continued = run(rest);
    EXPECT_EQ(continued.reason, render::StopReason::ReachedSpp);
    EXPECT_EQ(continued.stats.spp_this_run, 3u);
    expect_same_film(continued.image.film, reference.image.film);
}

}  // namespace
}  // namespace orb::job::test
