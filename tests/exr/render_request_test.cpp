// judge_output, the one definition of a finished output: each setting the
// header records against the request, the samples rule for whole frames and
// for slices, HALF files, and the scene's identity asked for last.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "orb/exr/render_request.h"
#include "test_film.h"

using namespace orb::exr;
using orb::exr::testing::scratch_path;
using orb::exr::testing::synthetic_film;
using orb::exr::testing::synthetic_metadata;

namespace {

constexpr int kWidth = 8, kHeight = 6;

// A file holding the samples `first`:`count`, stored as the options say.
std::string file_with(const std::string& name, std::uint64_t first, std::uint64_t count, bool half = false) {
    orb::Film film = synthetic_film(kWidth, kHeight, count);
    film.sample_ranges = orb::SampleRanges(orb::SampleRange{first, count});
    ExrWriteOptions options;
    options.half = half;
    options.passes = {Pass::Beauty};
    const std::string path = scratch_path(name);
    write_film_exr(path, film, synthetic_metadata(), options);
    return path;
}

// What the synthetic metadata holds, asked for in full.
RenderRequest request_for_metadata(std::uint64_t spp) {
    const ExrMetadata m = synthetic_metadata();
    RenderRequest r;
    r.scene = [m] { return SceneIdentity{m.scene_hash, m.world_to_camera, m.world_to_ndc}; };
    r.scene_time = m.scene_time;
    r.width = kWidth;
    r.height = kHeight;
    r.mode = m.mode;
    r.sampler = m.sampler;
    r.max_depth = m.max_depth;
    r.seed = m.seed;
    r.passes = std::vector<Pass>{Pass::Beauty};
    r.half = false;
    r.spp = spp;
    return r;
}

}  // namespace

TEST(RenderRequest, AWholeFrameIsFinishedWithAtLeastTheSamplesAskedAndContinuedWithFewer) {
    const std::string path = file_with("whole.exr", 0, 8);
    EXPECT_EQ(judge_output(path, request_for_metadata(8)).state, OutputState::Finished);
    EXPECT_EQ(judge_output(path, request_for_metadata(4)).state, OutputState::Finished);
    const OutputJudgement more = judge_output(path, request_for_metadata(16));
    EXPECT_EQ(more.state, OutputState::Continuable);
    EXPECT_EQ(more.reason, "holds 8 of 16 spp");
    EXPECT_EQ(more.held_spp, 8u);
    // Samples not from 0 are not the start of a whole frame.
    const OutputJudgement slice = judge_output(file_with("slice.exr", 8, 8), request_for_metadata(16));
    EXPECT_EQ(slice.state, OutputState::Different);
    EXPECT_EQ(slice.reason, "holds the samples 8:8, not a whole frame's from sample 0");
}

// An adaptive render that ended on its rule (orb:adaptiveStop) is finished
// short of its samples; one that did not is continued; other adaptive
// settings are another render; a request that does not say (orb-frames)
// does not compare them.
TEST(RenderRequest, AnAdaptiveRenderThatStoppedOnItsRuleIsFinished) {
    const auto adaptive_file = [](const std::string& name, std::optional<AdaptiveStop> stop) {
        orb::Film film = synthetic_film(kWidth, kHeight, 40);
        ExrMetadata m = synthetic_metadata();
        m.noise_threshold = 0.05;
        m.adaptive_stop = stop;
        ExrWriteOptions options;
        options.passes = {Pass::Beauty};
        const std::string path = scratch_path(name);
        write_film_exr(path, film, m, options);
        return path;
    };
    const std::string stopped = adaptive_file("stopped.exr", AdaptiveStop::Noise);
    EXPECT_EQ(read_film_exr(stopped).metadata.adaptive_stop, AdaptiveStop::Noise);
    RenderRequest r = request_for_metadata(4096);
    r.adaptive = RenderRequest::Adaptive{0.05, std::nullopt};
    const OutputJudgement finished = judge_output(stopped, r);
    EXPECT_EQ(finished.state, OutputState::Finished);
    EXPECT_EQ(finished.held_spp, 40u);
    const std::string short_of_it = adaptive_file("short.exr", std::nullopt);
    EXPECT_EQ(judge_output(short_of_it, r).state, OutputState::Continuable);
    r.adaptive->noise_threshold = 0.02;
    EXPECT_EQ(judge_output(stopped, r).reason, "rendered with --noise-threshold 0.05, 0.02 asked");
    r.adaptive = RenderRequest::Adaptive{};
    EXPECT_EQ(judge_output(stopped, r).reason, "rendered with --noise-threshold 0.05, none asked");
    r.adaptive = RenderRequest::Adaptive{0.05, 0.001};
    EXPECT_EQ(judge_output(stopped, r).reason, "rendered with --target-error none, 0.001 asked");
    r.adaptive.reset();
    EXPECT_EQ(judge_output(stopped, r).state, OutputState::Finished);
}

TEST(RenderRequest, ASliceMustHoldExactlyItsSamples) {
    RenderRequest r = request_for_metadata(8);
    r.slice = true;
    r.first_sample = 8;
    EXPECT_EQ(judge_output(file_with("exact.exr", 8, 8), r).state, OutputState::Finished);
    const OutputJudgement start = judge_output(file_with("start.exr", 8, 3), r);
    EXPECT_EQ(start.state, OutputState::Continuable);
    EXPECT_EQ(start.reason, "holds the samples 8:3 of 8:8");
    EXPECT_EQ(judge_output(file_with("more.exr", 8, 9), r).state, OutputState::Different);  // would overlap the next slice
    EXPECT_EQ(judge_output(file_with("other.exr", 0, 8), r).reason, "holds the samples 0:8, 8:8 asked");
}

TEST(RenderRequest, EverySettingTheHeaderRecordsIsCompared) {
    const std::string path = file_with("settings.exr", 0, 8);
    const struct {
        void (*change)(RenderRequest&);
        const char* reason;
    } cases[] = {
        {[](RenderRequest& r) { r.width = 16; }, "rendered at 8x6, 16x6 asked"},
        {[](RenderRequest& r) { r.passes = std::vector<Pass>{Pass::Beauty, Pass::Albedo}; },
         "holds the layers 'beauty', 'beauty,albedo' asked"},
        {[](RenderRequest& r) { r.half = true; }, "stored as FLOAT, HALF (--half) asked"},
        {[](RenderRequest& r) { r.mode = "global"; }, "rendered with --mode direct, global asked"},
        {[](RenderRequest& r) { r.max_depth = 1; }, "rendered with --max-depth"},
        {[](RenderRequest& r) { r.seed = 99; }, "rendered with another seed (orb:seed"},
        {[](RenderRequest& r) { r.scene_time = 7.5; }, "rendered at scene time"},
        {[](RenderRequest& r) {
             const auto old = r.scene;
             r.scene = [old] {
                 SceneIdentity moved = old();
                 moved.world_to_camera[3][0] += 1.0f;
                 return moved;
             };
         },
         "rendered from another camera"},
        {[](RenderRequest& r) {
             const auto old = r.scene;
             r.scene = [old] {
                 // The same camera made orthographic: only the projection differs.
                 orb::Camera camera;
                 camera.orthographic_height = 2;
                 SceneIdentity orthographic = old();
                 orthographic.world_to_ndc = world_to_ndc(camera, kWidth, kHeight);
                 return orthographic;
             };
         },
         "rendered from another camera (perspective, an orthographic one asked)"},
        {[](RenderRequest& r) {
             const auto old = r.scene;
             r.scene = [old] {
                 SceneIdentity edited = old();
                 edited.hash = "fedcba9876543210";
                 return edited;
             };
         },
         "rendered from another scene (orb:sceneHash "},
    };
    for (const auto& c : cases) {
        RenderRequest r = request_for_metadata(8);
        c.change(r);
        const OutputJudgement verdict = judge_output(path, r);
        EXPECT_EQ(verdict.state, OutputState::Different) << c.reason;
        EXPECT_EQ(verdict.reason.rfind(c.reason, 0), 0u) << verdict.reason;
    }
}

TEST(RenderRequest, TheSceneIsAskedForOnlyWhenEverythingElseMatches) {
    const std::string path = file_with("lazy.exr", 0, 8);
    int asked = 0;
    RenderRequest r = request_for_metadata(8);
    const auto identity = r.scene;
    r.scene = [&] {
        ++asked;
        return identity();
    };
    r.width = 4;
    EXPECT_EQ(judge_output(path, r).state, OutputState::Different);
    EXPECT_EQ(asked, 0);
    r.width = kWidth;
    EXPECT_EQ(judge_output(path, r).state, OutputState::Finished);
    EXPECT_EQ(asked, 1);
}

TEST(RenderRequest, AHalfFileIsFinishedWhenHalfIsAskedButNeverContinued) {
    const std::string path = file_with("half.exr", 0, 8, /*half=*/true);
    RenderRequest r = request_for_metadata(8);
    r.half = true;
    EXPECT_EQ(judge_output(path, r).state, OutputState::Finished);
    r.spp = 16;
    const OutputJudgement more = judge_output(path, r);
    EXPECT_EQ(more.state, OutputState::Different);
    EXPECT_EQ(more.reason, "holds 8 of 16 spp, stored as HALF, which cannot be continued exactly");
}

TEST(RenderRequest, MissingUnreadableAndUnaskedFields) {
    EXPECT_EQ(judge_output(scratch_path("absent.exr"), request_for_metadata(8)).state, OutputState::Missing);
    const std::string text = scratch_path("text.exr");
    std::ofstream(text) << "not an image";
    const OutputJudgement unreadable = judge_output(text, request_for_metadata(8));
    EXPECT_EQ(unreadable.state, OutputState::Different);
    EXPECT_EQ(unreadable.reason, "unreadable (not an OpenEXR file)");
    // Nothing asked: finished when it reached the target it was rendered toward (orb:targetSpp 64).
    EXPECT_EQ(judge_output(file_with("own-target.exr", 0, 64), RenderRequest{}).state, OutputState::Finished);
    const OutputJudgement short_of_it = judge_output(file_with("short.exr", 0, 8), RenderRequest{});
    EXPECT_EQ(short_of_it.state, OutputState::Continuable);
    EXPECT_EQ(short_of_it.reason, "holds 8 of 64 spp");
}

TEST(RenderRequest, AFileOfOtherKernelsIsAnotherRender) {
    const std::string path = file_with("kernel.exr", 0, 8);
    RenderRequest same = request_for_metadata(8);
    same.kernel = synthetic_metadata().kernel;
    EXPECT_EQ(judge_output(path, same).state, OutputState::Finished);
    RenderRequest other = request_for_metadata(16);  // fewer samples than asked: still not continued
    other.kernel = "9a0b1c2d3e4f5061";
    const OutputJudgement judged = judge_output(path, other);
    EXPECT_EQ(judged.state, OutputState::Different);
    EXPECT_EQ(judged.reason, "rendered by other kernels (orb:kernel 5f3a9c0e1d2b4a68, these are 9a0b1c2d3e4f5061)");
    EXPECT_EQ(judge_output(path, request_for_metadata(8)).state, OutputState::Finished);  // not asked: not compared
}

TEST(RenderRequest, AFileThatDoesNotNameItsKernelsIsAnotherRender) {
    orb::Film film = synthetic_film(kWidth, kHeight, 8);
    ExrMetadata old = synthetic_metadata();
    old.kernel.clear();  // as an older Orb wrote it
    ExrWriteOptions options;
    options.passes = {Pass::Beauty};
    const std::string path = scratch_path("old.exr");
    write_film_exr(path, film, old, options);
    RenderRequest asked = request_for_metadata(8);
    asked.kernel = "9a0b1c2d3e4f5061";
    const OutputJudgement judged = judge_output(path, asked);
    EXPECT_EQ(judged.state, OutputState::Different);
    EXPECT_EQ(judged.reason, "rendered by kernels it does not name (no orb:kernel: an older Orb), these are 9a0b1c2d3e4f5061");
}
