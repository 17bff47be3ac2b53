// One film rendered into its output (orb/job/output_film.h), as a still and
// every frame render: where it starts (a resumed film, or empty at its first
// sample), checkpoints written to the output, the progress told from start to
// finish, a stop before the first pass, the stats of the written image; and
// the progress estimate a progress line shows.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "job_test_support.h"
#include "orb/exr/film_exr.h"
#include "orb/job/film_progress.h"
#include "orb/job/output_film.h"

namespace orb::job::test {
namespace {

using OutputFilm = JobTest;

// An output kept in memory: every write, in order.
class MemoryOutput final : public ImageOutput {
public:
    explicit MemoryOutput(std::string path) : path_(std::move(path)) {}
    void stage(std::string_view bytes) override { staged_ = bytes; }
    void commit(std::string_view bytes) override {
        EXPECT_EQ(bytes, staged_) << "commit puts in place what was staged";
        writes.emplace_back(bytes);
    }
    std::string display_name() const override { return "memory " + path_; }
    std::string path() const override { return path_; }

    std::vector<std::string> writes;

private:
    std::string path_;
    std::string staged_;
};

// What the progress heard, in order: "start LABEL PIXELS", "pass SPP",
// "checkpoint OUTPUT SPP", "finish SPP".
class RecordingProgress final : public FilmProgress {
public:
    void start(const std::string& label, double pixels) override {
        events.push_back("start " + label + std::to_string(static_cast<int>(pixels)));
    }
    void on_pass(const render::ProgressState& s) override { events.push_back("pass " + std::to_string(s.spp)); }
    void on_checkpoint(const render::ProgressState& s, const std::string& output) override {
        events.push_back("checkpoint " + output + " " + std::to_string(s.spp));
    }
    void finish(const render::ProgressState& s) override { events.push_back("finish " + std::to_string(s.spp)); }

    std::vector<std::string> events;
};

TEST_F(OutputFilm, WritesEachCheckpointToItsOutputAndTellsTheProgressFromStartToFinish) {
    const Scene scene = orb::test::small_scene();
    RenderPlan still = plan(scene, still_options(scene, 8, 6, 4, 3));
    render::Renderer renderer(still.scene, still.config);
    start_film(still, renderer);
    MemoryOutput output("out.exr");
    RecordingProgress progress;
    OutputRun run;
    run.checkpoint = 1e-9;  // a checkpoint after every pass that is not the last
    run.progress = &progress;
    FilmOutcome outcome = render_into(renderer, still, run, output, "frame 3: ");
    ASSERT_TRUE(outcome.rendered);
    EXPECT_EQ(outcome.reason, render::StopReason::ReachedSpp);
    EXPECT_EQ(outcome.stats.output, "out.exr");

    // One sample a pass: passes at 1, 2, 3, 4 spp, a checkpoint after each of the first three.
    EXPECT_EQ(progress.events,
              (std::vector<std::string>{"start frame 3: 48", "pass 1", "checkpoint memory out.exr 1", "pass 2",
                                        "checkpoint memory out.exr 2", "pass 3", "checkpoint memory out.exr 3",
                                        "pass 4", "finish 4"}));
    // The checkpoints are the output's writes (the final image is the caller's
    // to write): whole images of the samples so far, with their exact sums.
    ASSERT_EQ(output.writes.size(), 3u);
    for (std::size_t i = 0; i < output.writes.size(); ++i) {
        const std::string file = path("checkpoint" + std::to_string(i) + ".exr");
        std::ofstream(file, std::ios::binary) << output.writes[i];
        const exr::ExrFilm written = exr::read_film_exr(file);
        EXPECT_EQ(written.film.samples_per_pixel, i + 1);
        EXPECT_TRUE(written.exact);
    }
}

TEST_F(OutputFilm, StoppedBeforeItsFirstPassItHasNoImageAndWritesNothing) {
    const Scene scene = orb::test::small_scene();
    RenderPlan still = plan(scene, still_options(scene, 8, 6, 4, 3));
    render::Renderer renderer(still.scene, still.config);
    start_film(still, renderer);
    MemoryOutput output("out.exr");
    RecordingProgress progress;
    const std::atomic<bool> stop{true};
    OutputRun run;
    run.checkpoint = 1e-9;
    run.cancel = &stop;
    run.progress = &progress;
    const FilmOutcome outcome = render_into(renderer, still, run, output);
    EXPECT_FALSE(outcome.rendered);
    EXPECT_EQ(outcome.reason, render::StopReason::Interrupted);
    EXPECT_TRUE(output.writes.empty());
    ASSERT_FALSE(progress.events.empty());
    EXPECT_EQ(progress.events.front(), "start 48");  // no label: a still
    EXPECT_EQ(progress.events.back(), "finish 0");
}

TEST_F(OutputFilm, AResumedFilmStartsFromItsSamplesAndSaysSo) {
    const Scene scene = orb::test::small_scene();
    RenderPlan first = plan(scene, still_options(scene, 8, 6, 4, 3));
    FilmOutcome stopped = run(first, 2);
    const std::string file = save(stopped, "stopped.exr");
    PlanOptions resume;
    resume.resume = file;
    RenderPlan rest = plan(scene, resume);
    render::Renderer renderer(rest.scene, rest.config);
    messages_.clear();  // a note of a kernel build, maybe
    start_film(rest, renderer);
    EXPECT_EQ(renderer.samples_per_pixel(), 2u);
    EXPECT_EQ(messages_, std::vector<std::string>{"resuming " + file + " at 2 spp (samples 0:2)"});
    MemoryOutput output("out.exr");
    const FilmOutcome outcome = render_into(renderer, rest, OutputRun{}, output);
    EXPECT_EQ(outcome.stats.spp, 4u);
    EXPECT_EQ(outcome.stats.spp_this_run, 2u);
    EXPECT_EQ(outcome.stats.sample_ranges, "0:4");
}

TEST_F(OutputFilm, AFreshFilmStartsEmptyAtItsFirstSample) {
    const Scene scene = orb::test::small_scene();
    PlanOptions options = still_options(scene, 8, 6, 4, 3);
    options.given.sample_range = SampleRange{5, 2};
    options.settings = resolve_settings(options.given, &scene.render);
    RenderPlan slice = plan(scene, options);
    render::Renderer renderer(slice.scene, slice.config);
    messages_.clear();  // a note of a kernel build, maybe
    start_film(slice, renderer);
    EXPECT_EQ(renderer.samples_per_pixel(), 0u);
    EXPECT_TRUE(messages_.empty());
    MemoryOutput output("slice.exr");
    const FilmOutcome outcome = render_into(renderer, slice, OutputRun{}, output);
    EXPECT_EQ(outcome.stats.sample_ranges, "5:2");
    EXPECT_FALSE(holds_samples_from_zero(renderer.sample_ranges()));
}

TEST_F(OutputFilm, TheWrittenStatsAddTheSetUpAndTheDenoisersTimes) {
    FilmOutcome outcome;
    outcome.stats.spp = 16;
    outcome.stats.output = "out.exr";
    RunStats stats = written_stats(outcome, 2.5);
    EXPECT_EQ(stats.setup_seconds, 2.5);
    EXPECT_FALSE(stats.denoise.has_value());
    EXPECT_EQ(stats.spp, 16u);
    EXPECT_EQ(stats.output, "out.exr");

    outcome.image.denoise_times = std::make_shared<denoise::DenoiseTimes>();
    outcome.image.denoise_times->seconds = 0.75;
    stats = written_stats(outcome, 2.5);
    ASSERT_TRUE(stats.denoise.has_value());
    EXPECT_EQ(stats.denoise->seconds, 0.75);
}

TEST(WrittenLine, SaysWhyTheRenderStoppedAndAStillNamesItsAdaptiveGoal) {
    using render::StopReason;
    EXPECT_EQ(written_line(StopReason::ReachedSpp, "S", true), "done: S");
    EXPECT_EQ(written_line(StopReason::ReachedTime, "S", true), "time limit reached: S");
    EXPECT_EQ(written_line(StopReason::Interrupted, "S", false), "interrupted: wrote S");
    EXPECT_EQ(written_line(StopReason::Converged, "S", true), "every pixel below --noise-threshold: S");
    EXPECT_EQ(written_line(StopReason::ReachedError, "S", true), "--target-error reached: S");
    EXPECT_EQ(written_line(StopReason::Converged, "S", false), "done: S");
    EXPECT_EQ(written_line(StopReason::ReachedError, "S", false), "done: S");
}

TEST(ProgressEstimate, TheRateGivesTheTimeToTheTargetAndATimeLimitCutsItShort) {
    render::ProgressState state;
    state.spp = 16;
    state.target_spp = 64;
    state.elapsed_seconds = 4;
    state.samples_per_second = 1000.0 * 4;  // 1000 pixels at 4 samples per pixel per second
    ProgressEstimate estimate = estimate_progress(state, 1000, 0);
    EXPECT_DOUBLE_EQ(estimate.fraction, 0.25);
    EXPECT_DOUBLE_EQ(estimate.eta_seconds, 12.0);  // 48 spp to go at 4 a second

    estimate = estimate_progress(state, 1000, 10);  // the limit comes 6 s from now, before the target
    EXPECT_DOUBLE_EQ(estimate.eta_seconds, 6.0);
    estimate = estimate_progress(state, 1000, 3);  // past the limit: the pass in flight is the last
    EXPECT_DOUBLE_EQ(estimate.eta_seconds, 0.0);

    state.spp = 80;  // past the target (a resumed film asked for fewer): done
    estimate = estimate_progress(state, 1000, 0);
    EXPECT_DOUBLE_EQ(estimate.fraction, 1.0);
    EXPECT_DOUBLE_EQ(estimate.eta_seconds, 0.0);
}

TEST(ProgressEstimate, WithoutARateTheEndIsUnknown) {
    render::ProgressState state;
    state.spp = 0;
    state.target_spp = 64;
    EXPECT_TRUE(std::isinf(estimate_progress(state, 1000, 0).eta_seconds));
    EXPECT_DOUBLE_EQ(estimate_progress(state, 1000, 0).fraction, 0.0);
    state.samples_per_second = 5000;
    EXPECT_TRUE(std::isinf(estimate_progress(state, 0, 0).eta_seconds));  // no pixels: no rate per pixel
    EXPECT_DOUBLE_EQ(estimate_progress(state, 0, 30).eta_seconds, 30.0);  // the time limit still ends it
    state.target_spp = 0;
    EXPECT_DOUBLE_EQ(estimate_progress(state, 1000, 0).fraction, 1.0);
}

}  // namespace
}  // namespace orb::job::test
