// The progressive loop's policy, against a fake renderer (no OpenCL): pass
// sizes, stopping rules, checkpoints, and the stop flag.
#include <gtest/gtest.h>

#include <numeric>

#include "fake_renderer.h"
#include "orb/render/progressive.h"

using namespace orb::render;

namespace {

struct LoopTest : ::testing::Test {
    void SetUp() override { fake::control() = {}; }

    fake::FakeRenderer make_renderer() { return fake::FakeRenderer(10 * 10); }
    std::atomic<bool> never{false};
};

std::uint64_t total(const std::vector<int>& passes) { return std::accumulate(passes.begin(), passes.end(), 0ull); }

}  // namespace

TEST_F(LoopTest, FirstPassIsOneSampleThenSuggestedSizesClampedToTheTarget) {
    fake::control().suggested = 4;
    fake::FakeRenderer renderer = make_renderer();
    ProgressiveLimits limits;
    limits.target_spp = 11;
    ProgressState state;
    EXPECT_EQ(render_progressively(renderer, limits, {}, never, &state), StopReason::ReachedSpp);
    EXPECT_EQ(fake::control().passes, (std::vector<int>{1, 4, 4, 2}));
    EXPECT_EQ(renderer.samples_per_pixel(), 11u);
    EXPECT_EQ(state.spp, 11u);
    EXPECT_EQ(state.pass, 4);
}

TEST_F(LoopTest, ResumedSamplesCountTowardTheTarget) {
    fake::FakeRenderer renderer = make_renderer();
    orb::Film resumed;
    resumed.samples_per_pixel = 9;
    renderer.load_film(resumed);
    ProgressiveLimits limits;
    limits.target_spp = 12;
    render_progressively(renderer, limits, {}, never);
    EXPECT_EQ(total(fake::control().passes), 3u);
    EXPECT_EQ(renderer.samples_per_pixel(), 12u);

    fake::control().passes.clear();
    render_progressively(renderer, limits, {}, never);  // already there: no pass at all
    EXPECT_TRUE(fake::control().passes.empty());
}

TEST_F(LoopTest, StopsAtTheTimeLimitWithoutOverrunningByMuch) {
    fake::control().seconds_per_sample = 0.01;
    fake::control().suggested = 50;  // 0.5 s passes unless shortened
    fake::FakeRenderer renderer = make_renderer();
    ProgressiveLimits limits;
    limits.target_spp = 1000000;
    limits.max_seconds = 0.3;
    ProgressState state;
    EXPECT_EQ(render_progressively(renderer, limits, {}, never, &state), StopReason::ReachedTime);
    EXPECT_GE(state.elapsed_seconds, 0.3);
    // Passes are cut to what the remaining time affords, so the overrun is
    // about one sample's time, not a whole 0.5 s pass (slack for a busy machine).
    EXPECT_LT(state.elapsed_seconds, 0.3 + 0.15);
    EXPECT_LT(renderer.samples_per_pixel(), 1000000u);
}

TEST_F(LoopTest, StopFlagEndsTheLoopAfterThePassInFlight) {
    std::atomic<bool> stop{false};
    fake::control().during_pass = [&](int index) {
        if (index == 2) stop = true;  // raised while the third pass runs
    };
    fake::FakeRenderer renderer = make_renderer();
    ProgressiveLimits limits;
    limits.target_spp = 1000;
    EXPECT_EQ(render_progressively(renderer, limits, {}, stop), StopReason::Interrupted);
    EXPECT_EQ(fake::control().passes.size(), 3u);  // that pass completed, no further one began
}

TEST_F(LoopTest, StopRequestedBeforeStartRendersNothing) {
    std::atomic<bool> stop{true};
    fake::FakeRenderer renderer = make_renderer();
    ProgressiveLimits limits;
    EXPECT_EQ(render_progressively(renderer, limits, {}, stop), StopReason::Interrupted);
    EXPECT_TRUE(fake::control().passes.empty());
}

TEST_F(LoopTest, CheckpointsAfterTheFirstPassThenEveryInterval) {
    fake::control().seconds_per_sample = 0.01;
    fake::control().suggested = 5;  // 50 ms passes
    fake::FakeRenderer renderer = make_renderer();
    ProgressiveLimits limits;
    limits.target_spp = 1 + 5 * 12;  // 12 full passes, about 0.6 s
    limits.checkpoint_seconds = 0.2;
    std::vector<ProgressState> checkpoints;
    int pass_calls = 0;
    ProgressiveCallbacks callbacks;
    callbacks.on_pass = [&](const ProgressState&) { ++pass_calls; };
    callbacks.on_checkpoint = [&](const ProgressState& s) { checkpoints.push_back(s); };
    render_progressively(renderer, limits, callbacks, never);

    EXPECT_EQ(pass_calls, 13);
    ASSERT_GE(checkpoints.size(), 2u);
    EXPECT_EQ(checkpoints.front().spp, 1u);  // the first image comes after the one-sample pass
    EXPECT_LE(checkpoints.size(), 5u);       // ~0.6 s / 0.2 s, plus the first
    for (std::size_t i = 1; i < checkpoints.size(); ++i)
        EXPECT_GE(checkpoints[i].elapsed_seconds - checkpoints[i - 1].elapsed_seconds, 0.2 - 1e-3);
    // None at the very end: the caller writes the final image anyway.
    EXPECT_LT(checkpoints.back().spp, limits.target_spp);
}

TEST_F(LoopTest, CheckpointsEveryGivenNumberOfPasses) {
    fake::control().suggested = 5;
    fake::FakeRenderer renderer = make_renderer();
    ProgressiveLimits limits;
    limits.target_spp = 1 + 5 * 12;  // 13 passes
    limits.checkpoint_passes = 4;
    std::vector<int> passes;
    ProgressiveCallbacks callbacks;
    callbacks.on_checkpoint = [&](const ProgressState& s) { passes.push_back(s.pass); };
    render_progressively(renderer, limits, callbacks, never);
    // The first pass's image, then every fourth pass while more follow (none after the last, pass 13).
    EXPECT_EQ(passes, (std::vector<int>{1, 5, 9}));
}

TEST_F(LoopTest, ReportsSamplesPerSecondOfThisRun) {
    fake::control().seconds_per_sample = 0.005;
    fake::control().suggested = 10;
    fake::FakeRenderer renderer = make_renderer();
    ProgressiveLimits limits;
    limits.target_spp = 21;
    ProgressState state;
    render_progressively(renderer, limits, {}, never, &state);
    // 100 pixels x 21 samples in ~0.105 s of sleeping: at most 2000 samples/s.
    EXPECT_GT(state.samples_per_second, 0);
    EXPECT_LE(state.samples_per_second, 100.0 * 21 / (0.005 * 21) * 1.01);
}
