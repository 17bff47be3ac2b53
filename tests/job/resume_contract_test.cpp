// The resume contract without the command line: a film continues only the
// render it was part of (scene, seed, size, kernel), and says why not.
#include <gtest/gtest.h>

#include "job_test_support.h"
#include "orb/scene/error.h"

namespace orb::job::test {
namespace {

class ResumeContract : public JobTest {
protected:
    // A render of 2 of 4 spp stopped short, in `partial.exr`.
    std::string partial(const Scene& scene) {
        RenderPlan first = plan(scene, still_options(scene, 8, 6, 4, 7));
        FilmOutcome stopped = run(first, 2);
        EXPECT_EQ(stopped.stats.spp, 2u);
        return save(stopped, "partial.exr");
    }
    PlanOptions resume(const std::string& file) {
        PlanOptions options;
        options.resume = file;
        return options;
    }
    // The plan is refused with a message that says `why`.
    void expect_refused(const Scene& scene, const PlanOptions& options, const std::string& why) {
        try {
            plan(scene, options);
            ADD_FAILURE() << "continued although " << why;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
        }
    }
};

TEST_F(ResumeContract, ContinuesTheSameRenderWithItsSettings) {
    const Scene scene = orb::test::small_scene();
    RenderPlan resumed = plan(scene, resume(partial(scene)));
    ASSERT_TRUE(resumed.resumed.has_value());
    EXPECT_EQ(resumed.resumed->film.samples_per_pixel, 2u);
    EXPECT_EQ(resumed.target_spp, 4u);  // orb:targetSpp
    EXPECT_EQ(resumed.config.seed, 7u);
    EXPECT_EQ(resumed.config.width, 8);
    EXPECT_EQ(resumed.config.height, 6);
}

TEST_F(ResumeContract, RefusesAnotherScene) {
    const Scene scene = orb::test::small_scene();
    const std::string file = partial(scene);
    Scene moved = scene;
    moved.spheres[1].center[0] += 0.25;
    expect_refused(moved, resume(file), "was rendered from a different scene");
}

TEST_F(ResumeContract, RefusesAnotherSeedOrSize) {
    const Scene scene = orb::test::small_scene();
    const std::string file = partial(scene);
    PlanOptions seed = resume(file);
    seed.given.seed = 8;
    expect_refused(scene, seed, "--seed 8 differs from the resumed render's orb:seed 7");
    PlanOptions width = resume(file);
    width.given.width = 16;
    expect_refused(scene, width, "--width 16 differs from the resumed render's width 8");
    // The same value may be repeated.
    PlanOptions same = resume(file);
    same.given.seed = 7;
    same.given.width = 8;
    EXPECT_NO_THROW(plan(scene, same));
}

TEST_F(ResumeContract, RefusesFewerSamplesThanTheFileHolds) {
    const Scene scene = orb::test::small_scene();
    PlanOptions fewer = resume(partial(scene));
    fewer.given.spp = 1;
    expect_refused(scene, fewer, "already holds 2 samples per pixel");
}

TEST_F(ResumeContract, RendersAFilmOfAnotherKernelAgainWithTheReason) {
    const Scene scene = orb::test::small_scene();
    const std::string file = partial(scene);
    render::DevelopmentKnobs other = one_sample_passes();
    other.cl_options = "-DORB_JOB_TEST_ANOTHER_KERNEL=1";  // another program: another orb:kernel
    RenderPlan again = plan(scene, resume(file), other);
    EXPECT_FALSE(again.resumed.has_value());
    EXPECT_EQ(again.first_sample, 0u);
    EXPECT_EQ(again.target_spp, 4u);
    EXPECT_EQ(again.config.seed, 7u);  // the file's settings stay
    ASSERT_EQ(messages_.size(), 1u);
    EXPECT_NE(messages_[0].find("rendering it again from its first sample"), std::string::npos) << messages_[0];
}

TEST_F(ResumeContract, ASliceContinuesOnlyFromItsStart) {
    const Scene scene = orb::test::small_scene();
    PlanOptions slice = still_options(scene, 8, 6, 4, 7);
    slice.given.sample_range = SampleRange{2, 2};
    slice.settings = resolve_settings(slice.given, &scene.render);
    RenderPlan first = plan(scene, slice);
    FilmOutcome stopped = run(first, 1);
    EXPECT_EQ(stopped.stats.sample_ranges, "2:1");
    const std::string file = save(stopped, "slice.exr");

    PlanOptions same = resume(file);
    same.given.sample_range = SampleRange{2, 2};
    same.sample_range_text = "2:2";
    RenderPlan rest = plan(scene, same);
    EXPECT_TRUE(rest.slice);
    EXPECT_EQ(rest.target_spp, 2u);
    EXPECT_EQ(run(rest).stats.sample_ranges, "2:2");

    PlanOptions other = resume(file);
    other.given.sample_range = SampleRange{0, 2};
    other.sample_range_text = "0:2";
    expect_refused(scene, other, "holds the samples 2:1, not the start of --sample-range 0:2");
}

}  // namespace
}  // namespace orb::job::test
