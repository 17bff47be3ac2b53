// The frame loop's pieces in the library: frames in the order asked, each
// posed with its own seed (also when posed ahead on another thread), and an
// output already finished judged so, to be skipped.
#include <gtest/gtest.h>

#include "job_test_support.h"
#include "orb/exr/render_request.h"
#include "orb/job/frame_jobs.h"

namespace orb::job::test {
namespace {

using FrameLoop = JobTest;

TEST_F(FrameLoop, FramesInTheOrderAskedEachWithItsSeedAndPose) {
    const Scene scene = orb::test::moving_ball_scene();
    PlanOptions options = still_options(scene, 8, 6, 2, 5);
    options.frames = {12, 3, 7};
    RenderPlan frames = plan(scene, options);
    EXPECT_EQ(frames.frames, (std::vector<long>{12, 3, 7}));

    std::optional<render::Renderer> renderer;
    PosePrefetch prefetch;
    std::vector<std::string> hashes;
    for (std::size_t i = 0; i < frames.frames.size(); ++i) {
        const Job job{frames.frames[i], path("frame" + std::to_string(frames.frames[i]) + ".exr")};
        prefetch.use_for(frames, job);
        set_up(frames, job, renderer);
        ASSERT_TRUE(posed_at(frames, frames.frames[i]));
        EXPECT_EQ(frames.config.seed, frames.settings.seed_of(frames.frames[i]));
        EXPECT_EQ(label_of(job), "frame " + std::to_string(frames.frames[i]) + ": ");
        if (i + 1 < frames.frames.size())
            prefetch.start(frames, Job{frames.frames[i + 1], ""}, *renderer);
        hashes.push_back(frames.scene_hash);
        // The pose the loop installed is the one a fresh pose of that frame gives.
        RenderPlan alone = plan(scene, options);
        pose_frame(alone, frames.frames[i]);
        EXPECT_EQ(alone.scene_hash, frames.scene_hash) << "frame " << frames.frames[i];
    }
    prefetch.use_for(frames, Job{});  // nothing left in flight
    EXPECT_NE(hashes[0], hashes[1]);  // the ball moves
    EXPECT_NE(hashes[1], hashes[2]);
}

TEST_F(FrameLoop, AFinishedFrameIsJudgedFinishedAndTheOthersNot) {
    const Scene scene = orb::test::moving_ball_scene();
    PlanOptions options = still_options(scene, 8, 6, 2, 5);
    options.frames = {1, 2};
    RenderPlan frames = plan(scene, options);
    const Job first{1, path("frame1.exr")};
    const Job second{2, path("frame2.exr")};

    std::optional<render::Renderer> renderer;
    set_up(frames, first, renderer);
    FilmRun run;
    FilmOutcome outcome = render_film(*renderer, frames, std::move(run));
    save(outcome, "frame1.exr");

    EXPECT_EQ(judge(frames, first).state, exr::OutputState::Finished);
    EXPECT_EQ(judge(frames, second).state, exr::OutputState::Missing);
    // Frame 1's file is no finished frame 2 (another pose, another seed).
    const Job misplaced{2, path("frame1.exr")};
    EXPECT_EQ(judge(frames, misplaced).state, exr::OutputState::Different);
}

TEST_F(FrameLoop, AStaticSceneSaysEveryFrameIsTheSame) {
    const Scene scene = orb::test::small_scene();
    PlanOptions options = still_options(scene, 8, 6, 2, 5);
    options.frames = {1, 2, 3};
    plan(scene, options);
    ASSERT_EQ(messages_.size(), 1u);
    EXPECT_NE(messages_[0].find("same image"), std::string::npos) << messages_[0];
}

TEST(FrameJobs, OnePerFrameInTheOrderGivenOrTheOneOutputOfAStill) {
    const auto name = [](long frame) { return "beauty." + std::to_string(frame) + ".exr"; };
    const std::vector<Job> frames = jobs_of({12, 3, 7}, "unused.exr", name);
    ASSERT_EQ(frames.size(), 3u);
    EXPECT_EQ(frames[0].frame, 12);
    EXPECT_EQ(frames[0].output, "beauty.12.exr");
    EXPECT_EQ(frames[2].frame, 7);
    EXPECT_EQ(frames[2].output, "beauty.7.exr");

    const std::vector<Job> still = jobs_of({}, "still.exr", name);
    ASSERT_EQ(still.size(), 1u);
    EXPECT_FALSE(still[0].frame.has_value());
    EXPECT_EQ(still[0].output, "still.exr");
    EXPECT_EQ(label_of(still[0]), "");
}

}  // namespace
}  // namespace orb::job::test
