// The frame loop (orb/job/frame_run.h) through the library alone: each
// frame rendered into its output and then left alone once finished,
// continued when stopped short, left to the host that claimed it, stopped
// between frames by the cancel flag; what --stats-json says of a run; and
// which outputs --missing names (frame_jobs.h's unfinished).
#include <gtest/gtest.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <mutex>

#include <nlohmann/json.hpp>

#include "job_test_support.h"
#include "orb/exr/render_request.h"
#include "orb/job/frame_claim.h"
#include "orb/job/frame_jobs.h"
#include "orb/job/frame_run.h"

namespace orb::job::test {
namespace {

class FrameRun : public JobTest {
protected:
    // Frames `frames` of the moving ball at `spp`; its messages (said from
    // the writer's threads too) kept in said_.
    RenderPlan frames_plan(std::vector<long> frames, std::uint64_t spp) {
        const Scene scene = orb::test::moving_ball_scene();
        PlanOptions options = still_options(scene, 8, 6, spp, 5);
        options.frames = std::move(frames);
        RenderPlan made = plan(scene, options);
        made.messages = [this](MessageKind, const std::string& message) {
            const std::lock_guard<std::mutex> lock(mutex_);
            said_.push_back(message);
        };
        return made;
    }
    std::vector<Job> jobs_of(const RenderPlan& plan) const {
        std::vector<Job> jobs;
        for (long frame : plan.frames) jobs.push_back({frame, path("frame" + std::to_string(frame) + ".exr")});
        return jobs;
    }
    // The hooks of a front end that writes files and says "S" of each frame written.
    FrameRunHooks hooks() {
        FrameRunHooks made;
        made.prepare_output = [](const Job& job) { return std::make_unique<FileOutput>(job.output); };
        made.summary = [](const FilmOutcome&, const render::Renderer&, const ImageOutput&) { return std::string("S"); };
        made.skipped = [this](const Job& job) { left_alone_.push_back(*job.frame); };
        return made;
    }
    bool said(const std::string& message) {
        const std::lock_guard<std::mutex> lock(mutex_);
        return std::find(said_.begin(), said_.end(), message) != said_.end();
    }

    std::mutex mutex_;
    std::vector<std::string> said_;
    std::vector<long> left_alone_;
};

TEST_F(FrameRun, RendersEachFrameIntoItsOutputThenLeavesThemAloneOnceFinished) {
    RenderPlan frames = frames_plan({3, 1, 2}, 2);
    const std::vector<Job> jobs = jobs_of(frames);
    FramesRun run = run_frames(frames, jobs, FrameRunOptions{}, hooks());
    ASSERT_EQ(run.rendered.size(), 3u);
    EXPECT_EQ(run.rendered[0].frame, 3);  // in the order asked
    EXPECT_EQ(run.rendered[1].frame, 1);
    EXPECT_EQ(run.rendered[0].output, jobs[0].output);
    EXPECT_EQ(run.kernel_builds, 1);  // one renderer for every frame
    EXPECT_TRUE(said("frame 2: done: S"));
    for (const Job& job : jobs) EXPECT_EQ(judge(frames, job).state, exr::OutputState::Finished) << job.output;

    FrameRunOptions skip;
    skip.skip_existing = true;
    run = run_frames(frames, jobs, skip, hooks());
    EXPECT_TRUE(run.rendered.empty());
    EXPECT_EQ(run.skipped, (std::vector<long>{3, 1, 2}));
    EXPECT_EQ(left_alone_, (std::vector<long>{3, 1, 2}));
    EXPECT_TRUE(said("frame 1: " + jobs[1].output + ": finished (2 spp); skipped"));
    const nlohmann::json stats = nlohmann::json::parse(frames_run_stats_json(frames, run));
    EXPECT_TRUE(stats["frames"].empty());
    EXPECT_EQ(stats["skipped"], nlohmann::json({3, 1, 2}));
}

TEST_F(FrameRun, ContinuesFramesStoppedShortOfTheirSamples) {
    RenderPlan two = frames_plan({1, 2}, 2);
    const std::vector<Job> jobs = jobs_of(two);
    run_frames(two, jobs, FrameRunOptions{}, hooks());

    RenderPlan four = frames_plan({1, 2}, 4);
    FrameRunOptions skip;
    skip.skip_existing = true;
    const FramesRun run = run_frames(four, jobs, skip, hooks());
    EXPECT_EQ(run.continued, 2);
    ASSERT_EQ(run.rendered.size(), 2u);
    for (const RunStats& frame : run.rendered) {
        EXPECT_EQ(frame.spp, 4u);
        EXPECT_EQ(frame.spp_this_run, 2u);  // the file's two samples kept
        EXPECT_EQ(frame.sample_ranges, "0:4");
    }
    for (const Job& job : jobs) EXPECT_EQ(judge(four, job).state, exr::OutputState::Finished) << job.output;
}

TEST_F(FrameRun, LeavesAFrameClaimedByAnotherHostToIt) {
    RenderPlan frames = frames_plan({1, 2, 3}, 1);
    const std::vector<Job> jobs = jobs_of(frames);
    std::ofstream(claim_path(jobs[1].output)) << "host another-host pid 4242 started " << std::time(nullptr) << "\n";
    FrameRunOptions claim;
    claim.claim = true;
    const FramesRun run = run_frames(frames, jobs, claim, hooks());
    EXPECT_EQ(run.claimed_elsewhere, 1);
    ASSERT_EQ(run.rendered.size(), 2u);
    EXPECT_EQ(run.rendered[0].frame, 1);
    EXPECT_EQ(run.rendered[1].frame, 3);
    EXPECT_TRUE(said("frame 2: " + jobs[1].output + " is claimed by host another-host pid 4242; skipped"));
    EXPECT_EQ(judge(frames, jobs[1]).state, exr::OutputState::Missing);
    // Each frame's own claim is gone once its image is in place.
    EXPECT_FALSE(std::filesystem::exists(claim_path(jobs[0].output)));
    EXPECT_FALSE(std::filesystem::exists(claim_path(jobs[2].output)));
}

TEST_F(FrameRun, TheCancelFlagStopsTheLoopBetweenFrames) {
    RenderPlan frames = frames_plan({1, 2, 3}, 1);
    const std::vector<Job> jobs = jobs_of(frames);
    std::atomic<bool> stop{false};
    FrameRunHooks stopping = hooks();
    stopping.summary = [&](const FilmOutcome&, const render::Renderer&, const ImageOutput&) {
        stop = true;  // as a signal arriving once frame 1's last pass is done
        return std::string("S");
    };
    FrameRunOptions options;
    options.film.cancel = &stop;
    const FramesRun run = run_frames(frames, jobs, options, stopping);
    ASSERT_EQ(run.rendered.size(), 1u);
    EXPECT_FALSE(run.stopped_before_image.has_value());
    EXPECT_EQ(judge(frames, jobs[0]).state, exr::OutputState::Finished);  // the frame in flight is written
    EXPECT_EQ(judge(frames, jobs[1]).state, exr::OutputState::Missing);
}

TEST_F(FrameRun, OneFrameAskedHasTheStatsOfOneRender) {
    RenderPlan frame = frames_plan({5}, 1);
    const FramesRun run = run_frames(frame, jobs_of(frame), FrameRunOptions{}, hooks());
    const nlohmann::json stats = nlohmann::json::parse(frames_run_stats_json(frame, run));
    EXPECT_FALSE(stats.contains("frames"));
    EXPECT_EQ(stats["frame"], 5);
    EXPECT_EQ(stats["spp"], 1);
    EXPECT_EQ(stats["output"], path("frame5.exr"));
}

TEST_F(FrameRun, UnfinishedOutputsAreTheAbsentAndTheOnesThatDoNotCountWithANoteForTheLatter) {
    RenderPlan frames = frames_plan({1, 2, 3}, 1);
    const std::vector<Job> jobs = jobs_of(frames);
    run_frames(frames, {jobs[0]}, FrameRunOptions{}, hooks());
    std::ofstream(jobs[2].output) << "not an EXR";
    said_.clear();

    const std::vector<Job> left = unfinished(frames, jobs);
    ASSERT_EQ(left.size(), 2u);
    EXPECT_EQ(left[0].frame, 2);
    EXPECT_EQ(left[1].frame, 3);
    ASSERT_EQ(said_.size(), 1u);  // the absent frame 2 says nothing new
    EXPECT_EQ(said_[0].rfind("frame 3: " + jobs[2].output + ": ", 0), 0u) << said_[0];

    // Another judgement (orb-frames --missing's): the same rule.
    const std::vector<Job> all = unfinished(
        jobs, [](const Job&) { return exr::OutputJudgement{exr::OutputState::Different, "another render", 0}; },
        frames.messages);
    EXPECT_EQ(all.size(), 3u);
    EXPECT_TRUE(said("frame 1: " + jobs[0].output + ": another render"));
}

}  // namespace
}  // namespace orb::job::test
