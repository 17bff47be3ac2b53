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
    try {
        plan(moved, resume(file));
        FAIL() << "a film of another scene was continued";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("was rendered from a different scene"), std::string::npos) << e.what();
    }
}

TEST_F(ResumeContract, RefusesAnotherSeedOrSize) {
    const Scene scene = orb::test::small_scene();
    const std::string file = partial(scene);
    PlanOptions seed = resume(file);
    seed.given.seed = 8;
    try {
        plan(scene, seed);
        FAIL() << "a film of another seed was continued";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--seed 8 differs from the resumed render's orb:seed 7"), std::string::npos)
            << e.what();
    }
    PlanOptions width = resume(file);
    width.given.width = 16;
    EXPECT_THROW(plan(scene, width), InputError);
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
    try {
        plan(scene, fewer);
        FAIL() << "a film was continued to fewer samples than it holds";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("already holds 2 samples per pixel"), std::string::npos) << e.what();
    }
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

}  // namespace
}  // namespace orb::job::test
