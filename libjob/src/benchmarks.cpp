#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>

#include "orb/job/benchmarks.h"
#include "orb/job/background_writer.h"
#include "orb/job/render_film.h"
#include "orb/job/seconds_since.h"
#include "orb/scene/error.h"

namespace orb::job {

FramesBenchmark run_frames_benchmark(RenderPlan& plan, const std::vector<Job>& jobs, int spp,
                                     const std::function<std::unique_ptr<ImageOutput>(const std::string& path)>& open_output,
                                     const std::function<void(render::Renderer&)>& renderer_made) {
    std::optional<render::Renderer> renderer;
    // The first frame pays for the kernel build and the driver's lazy set-up:
    // rendered once before timing.
    set_up(plan, jobs.front(), renderer, renderer_made);
    renderer->render_pass(1);

    // The EXRs are written as real frames are (on the writer's thread, to a
    // temporary file that is flushed and renamed), into a private folder
    // that is removed afterwards.
    const char* tmp = std::getenv("TMPDIR");
    std::string folder = std::string(tmp && *tmp ? tmp : "/tmp") + "/orb-frames-benchmark-XXXXXX";
    if (!::mkdtemp(folder.data())) throw InputError(folder + ": cannot make a folder for the benchmark's frames");

    // With fewer samples than it takes to write a frame, the writer's time shows as waiting.
    FramesBenchmark bench;
    bench.phases = {{"pose"}, {"upload"}, {"render (" + std::to_string(spp) + " spp)"}, {"read back"},
                    {"wait for writer"}, {"alone: encode"}, {"alone: write+fsync"}};
    FramesBenchmark::Phase& pose = bench.phases[0];
    FramesBenchmark::Phase& upload = bench.phases[1];
    FramesBenchmark::Phase& render_phase = bench.phases[2];
    FramesBenchmark::Phase& read = bench.phases[3];
    FramesBenchmark::Phase& wait = bench.phases[4];
    FramesBenchmark::Phase& encode = bench.phases[5];
    FramesBenchmark::Phase& write = bench.phases[6];
    exr::ExrWriteOptions write_options;
    write_options.passes = plan.passes;
    write_options.half = plan.half;
    write_options.compression = plan.compression;
    try {
        PosePrefetch prefetch;
        BackgroundWriter writer(plan.messages);
        for (std::size_t i = 0; i < jobs.size(); ++i) {
            const Job& job = jobs[i];
            // As a real run does: this frame's pose was started while the
            // last frame rendered; only the wait for it is on the render path.
            Clock::time_point t = Clock::now();
            prefetch.use_for(plan, job);
            pose_for(plan, job);
            pose.add(seconds_since(t));
            t = Clock::now();
            upload_changed_scene(plan, *renderer);
            renderer->set_seed(plan.config.seed);
            renderer->clear(plan.first_sample);
            upload.add(seconds_since(t));
            if (i + 1 < jobs.size()) prefetch.start(plan, jobs[i + 1], *renderer);
            t = Clock::now();
            for (int done = 0; done < spp;) {
                const int pass = std::min(spp - done, std::max(1, renderer->suggested_samples_per_pass()));
                renderer->render_pass(pass);
                done += pass;
            }
            render_phase.add(seconds_since(t));
            t = Clock::now();
            FinalImage image{writer.take_spare_film(), plan_metadata(plan), write_options, std::nullopt};
            image.messages = plan.messages;
            image.arriving = renderer->read_film_later();
            read.add(seconds_since(t));
            const double waited_before = writer.seconds_waited();
            writer.submit({std::move(image), open_output(folder + "/frame" + std::to_string(i) + ".exr"), std::nullopt,
                           "", "", false});
            wait.add(writer.seconds_waited() - waited_before);
        }
        writer.finish();
        // The writer's own time, measured apart from rendering: one frame
        // encoded, then written (temporary file, fsync, rename), alone.
        // Its memory is reused from frame to frame, as the writer's is.
        const std::size_t alone = std::min<std::size_t>(jobs.size(), 4);
        exr::ExrEncoding encoding;
        for (std::size_t i = 0; i < alone; ++i) {
            FinalImage image{renderer->read_film(), plan_metadata(plan), write_options, std::nullopt};
            image.messages = plan.messages;
            Clock::time_point t = Clock::now();
            image.encode(encoding);
            encode.add(seconds_since(t));
            bench.bytes_per_frame = encoding.bytes().size();
            t = Clock::now();
            open_output(folder + "/alone.exr")->write(encoding.bytes());
            write.add(seconds_since(t));
        }
        for (FramesBenchmark::Phase* phase : {&encode, &write})
            phase->total *= static_cast<double>(jobs.size()) / static_cast<double>(alone);
    } catch (...) {
        std::filesystem::remove_all(folder);
        throw;
    }
    std::filesystem::remove_all(folder);

    bench.frames = jobs.size();
    bench.kernel_builds = renderer->programs_built();
    const double n = static_cast<double>(jobs.size());
    bench.overhead_ms = 1000.0 * (pose.total + upload.total + read.total + wait.total) / n;
    return bench;
}

void FramesBenchmark::Phase::add(double seconds) {
    total += seconds;
    most = std::max(most, seconds);
}

ReadyRenderer make_ready_renderer(const RenderPlan& plan) {
    const auto began = std::chrono::steady_clock::now();
    ReadyRenderer ready{std::make_unique<render::Renderer>(plan.scene, plan.config), 0, 0};
    ready.construct_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    ready.setup_seconds = plan.read_seconds + ready.construct_seconds;
    return ready;
}

StillBenchmark run_still_benchmark(const ReadyRenderer& ready, double seconds) {
    render::Renderer& renderer = *ready.renderer;
    StillBenchmark bench{render::run_benchmark(renderer, seconds), renderer_stats(renderer)};
    RunStats& stats = bench.stats;
    stats.spp_this_run = stats.spp;
    stats.samples_this_run = stats.samples;
    stats.passes = bench.result.passes;
    stats.seconds = bench.result.seconds;
    stats.samples_per_second = bench.result.samples_per_second;
    stats.stop_reason = "benchmark";
    stats.setup_seconds = ready.setup_seconds;
    return bench;
}

}  // namespace orb::job
