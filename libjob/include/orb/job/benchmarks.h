// The renderer a plan runs on, ready to render, with the seconds it took;
// and the benchmarks orb-render --benchmark runs: the speed of a still's
// passes, and (with --frames) what a frame costs besides its samples.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
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

// --benchmark --frames: each phase of a frame's cost, timed over the frames.
struct FramesBenchmark {
    struct Phase {
        std::string name;
        double total = 0, most = 0;  // seconds over every frame, and the longest
        void add(double seconds);
    };
    std::vector<Phase> phases;  // pose, upload, render, read back, wait for writer, alone: encode, alone: write+fsync
    std::size_t frames = 0;
    std::size_t bytes_per_frame = 0;
    int kernel_builds = 0;
    double overhead_ms = 0;  // the mean time a frame adds to the render path besides its samples
};
// Renders `jobs` at `spp` samples each as a frame run does, writing each
// frame through `open_output` (orb-render writes them as its real frames,
// into a private folder it removes), then encodes and writes a few frames
// alone. `renderer_made` hears of the renderer once it exists.
FramesBenchmark run_frames_benchmark(RenderPlan& plan, const std::vector<Job>& jobs, int spp,
                                     const std::function<std::unique_ptr<ImageOutput>(const std::string& path)>& open_output,
                                     const std::function<void(render::Renderer&)>& renderer_made);

}  // namespace orb::job
