// The renderer a plan runs on, ready to render, with the seconds it took;
// and the benchmarks orb-render --benchmark runs: the speed of a still's
// passes, and (with --frames) what a frame costs besides its samples.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "orb/job/frame_jobs.h"
#include "orb/job/image_output.h"
#include "orb/job/render_plan.h"
#include "orb/job/run_stats.h"
#include "orb/render/renderer.h"

namespace orb::job {

// The renderer for `plan`, and the seconds from reading the scene until it
// could render: a million spheres take seconds before the first pass.
struct ReadyRenderer {
    std::unique_ptr<render::Renderer> renderer;
    double setup_seconds = 0;      // plan.read_seconds and constructing the renderer
    double construct_seconds = 0;  // constructing it: the tree, the kernels, the upload
};
ReadyRenderer make_ready_renderer(const RenderPlan& plan);

// --benchmark: passes for `seconds` on a ready renderer; the stats say what
// --stats-json says of it (stop reason "benchmark").
struct StillBenchmark {
    render::BenchmarkResult result;
    RunStats stats;
};
StillBenchmark run_still_benchmark(const ReadyRenderer& ready, double seconds);

// --benchmark --frames: what a frame costs besides its samples, timed over
// the frames as a real run renders and writes them, then its writing alone.
struct FramesBenchmark {
    struct Phase {
        std::string name;
        double total = 0, most = 0;  // seconds over every time timed, and the longest
        int count = 0;
        void add(double seconds);
        double mean_ms() const { return count ? 1000.0 * total / count : 0.0; }
    };
    // " name mean (max);" for each phase, in milliseconds.
    static std::string format(const std::vector<Phase>& phases);

    // 1. Each frame of the loop: pose, upload, render, read back (started), wait for writer.
    std::vector<Phase> loop;
    double last_writes_ms = 0;  // the frames still being written once the last had rendered
    double loop_ms = 0;         // the loop's pace, milliseconds a frame
    // 2. One frame's writing alone, step by step: read back, denoise (with
    // --denoise), encode, write+fsync, rename.
    std::vector<Phase> alone;
    // 3. The writer alone, `writer_frames` frames: milliseconds a frame with N
    // frames written at once (N: 1, 2, 4, ... up to `in_flight`).
    std::vector<std::pair<std::size_t, double>> writer_pace;
    std::size_t writer_frames = 0;
    std::string writer_pace_text() const;  // "1: 40.2; 2: 22.5; 3: 18.0"

    std::size_t frames = 0;
    std::size_t in_flight = 0;  // frames written at once (the plan's frames_in_flight)
    std::size_t bytes_per_frame = 0;
    int kernel_builds = 0;
    double overhead_ms = 0;  // the mean time a frame adds to the render path besides its samples
};
// Renders `jobs` at `spp` samples each as a frame run does, writing each
// frame through `open_output` (orb-render writes them as its real frames,
// into a private folder removed afterwards), then writes a few frames alone
// step by step and the writer alone at 1, 2, 4, ... frames at once.
// `renderer_made` hears of the renderer once it exists.
FramesBenchmark run_frames_benchmark(RenderPlan& plan, const std::vector<Job>& jobs, int spp,
                                     const std::function<std::unique_ptr<ImageOutput>(const std::string& path)>& open_output,
                                     const std::function<void(render::Renderer&)>& renderer_made);

}  // namespace orb::job
