// Judging an output against what a plan asks (--skip-existing, orb-frames
// --missing, orb-farm): finished, short of its samples, of another kernel.
#include <gtest/gtest.h>

#include "job_test_support.h"
#include "orb/exr/render_request.h"

namespace orb::job::test {
namespace {

using JudgeOutputs = JobTest;

TEST_F(JudgeOutputs, FinishedShortMissingAndAnotherKernel) {
    const Scene scene = orb::test::small_scene();
    RenderPlan four = plan(scene, still_options(scene, 8, 6, 4, 3));
    FilmOutcome finished = run(four);
    const std::string finished_file = save(finished, "finished.exr");
    FilmOutcome stopped = run(four, 1);
    const std::string short_file = save(stopped, "short.exr");

    exr::OutputJudgement verdict = exr::judge_output(finished_file, request_for(four, std::nullopt));
    EXPECT_EQ(verdict.state, exr::OutputState::Finished) << verdict.reason;
    EXPECT_EQ(verdict.held_spp, 4u);

    verdict = exr::judge_output(short_file, request_for(four, std::nullopt));
    EXPECT_EQ(verdict.state, exr::OutputState::Continuable) << verdict.reason;
    EXPECT_EQ(verdict.held_spp, 1u);

    verdict = exr::judge_output(path("none.exr"), request_for(four, std::nullopt));
    EXPECT_EQ(verdict.state, exr::OutputState::Missing);

    // The same settings with another kernel: another render.
    render::DevelopmentKnobs other = one_sample_passes();
    other.cl_options = "-DORB_JOB_TEST_ANOTHER_KERNEL=1";
    RenderPlan other_kernel = plan(scene, still_options(scene, 8, 6, 4, 3), other);
    verdict = exr::judge_output(finished_file, request_for(other_kernel, std::nullopt));
    EXPECT_EQ(verdict.state, exr::OutputState::Different) << verdict.reason;
    EXPECT_EQ(verdict.reason, exr::another_kernel(four.kernel, other_kernel.kernel));

    // More samples asked of a finished file: it continues.
    RenderPlan eight = plan(scene, still_options(scene, 8, 6, 8, 3));
    verdict = exr::judge_output(finished_file, request_for(eight, std::nullopt));
    EXPECT_EQ(verdict.state, exr::OutputState::Continuable) << verdict.reason;
}

}  // namespace
}  // namespace orb::job::test
