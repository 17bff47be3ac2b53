#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "orb/job/benchmarks.h"
#include "orb/job/background_writer.h"
#include "orb/job/render_film.h"
#include "orb/job/seconds_since.h"
#include "orb/scene/error.h"

namespace orb::job {
namespace {

// A private folder for the benchmark's EXRs, removed however it ends.
struct ScratchFolder {
    std::string path;
    ScratchFolder() {
        const char* tmp = std::getenv("TMPDIR");
        path = std::string(tmp && *tmp ? tmp : "/tmp") + "/orb-frames-benchmark-XXXXXX";
        if (!::mkdtemp(path.data())) throw InputError(path + ": cannot make a folder for the benchmark's frames");
    }
    ~ScratchFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
    std::string file(const std::string& name) const { return path + "/" + name; }
};

using OpenOutput = std::function<std::unique_ptr<ImageOutput>(const std::string& path)>;

// The final image of the film on the device, as a frame's is: read back
// while the caller goes on, with the denoised layer when --denoise.
FinalImage image_of(const RenderPlan& plan, render::Renderer& renderer, const exr::ExrWriteOptions& options,
                    Film reuse) {
    FinalImage image{std::move(reuse), plan_metadata(plan), options, std::nullopt};
    image.messages = plan.messages;
    image.arriving = renderer.read_film_later();
    image.denoiser = plan.denoiser;
    if (plan.denoiser) image.denoise_times = std::make_shared<denoise::DenoiseTimes>();
    return image;
}

// The writer alone: `frames` frames of the film on the device read back and
// written through a BackgroundWriter of `in_flight` frames, as fast as it
// takes them. Returns milliseconds a frame.
double writer_ms_per_frame(const RenderPlan& plan, render::Renderer& renderer, const exr::ExrWriteOptions& options,
                           const ScratchFolder& folder, const OpenOutput& open_output, std::size_t frames,
                           std::size_t in_flight) {
    const Clock::time_point start = Clock::now();
    BackgroundWriter writer(plan.messages, in_flight);
    for (std::size_t i = 0; i < frames; ++i)
        writer.submit({image_of(plan, renderer, options, writer.take_spare_film()),
                       open_output(folder.file("writer" + std::to_string(i) + ".exr")), std::nullopt, "", "", false});
    writer.finish();
    return 1000.0 * seconds_since(start) / static_cast<double>(frames);
}

}  // namespace

FramesBenchmark run_frames_benchmark(RenderPlan& plan, const std::vector<Job>& jobs, int spp,
                                     const OpenOutput& open_output,
                                     const std::function<void(render::Renderer&)>& renderer_made) {
    std::optional<render::Renderer> renderer;
    // The first frame pays for the kernel build and the driver's lazy set-up:
    // rendered once before timing.
    set_up(plan, jobs.front(), renderer, renderer_made);
    renderer->render_pass(1);

    // The EXRs are written as real frames are (on the writer's threads, to
    // temporary files that are flushed and renamed), into a private folder.
    const ScratchFolder folder;

    // With fewer samples than it takes to write a frame, the writer's time shows as waiting.
    FramesBenchmark bench;
    bench.loop = {{"pose"}, {"upload"}, {"render (" + std::to_string(spp) + " spp)"}, {"read back (started)"},
                  {"wait for writer"}};
    FramesBenchmark::Phase& pose = bench.loop[0];
    FramesBenchmark::Phase& upload = bench.loop[1];
    FramesBenchmark::Phase& render_phase = bench.loop[2];
    FramesBenchmark::Phase& read = bench.loop[3];
    FramesBenchmark::Phase& wait = bench.loop[4];
    FramesBenchmark::Phase arrive{"read back"}, denoise_phase{"denoise"}, encode{"encode"}, stage{"write+fsync"},
        place{"rename"};
    exr::ExrWriteOptions write_options;
    write_options.passes = plan.passes;
    write_options.half = plan.half;
    write_options.compression = plan.compression;
    bench.in_flight = std::max<std::size_t>(1, plan.frames_in_flight);
    const double n = static_cast<double>(jobs.size());

    // 1. The frame loop as a real run goes through it: what each frame adds
    // to the render path besides its samples, and the loop's own pace.
    const Clock::time_point loop_start = Clock::now();
    {
        PosePrefetch prefetch;
        BackgroundWriter writer(plan.messages, bench.in_flight);
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
            FinalImage image = image_of(plan, *renderer, write_options, writer.take_spare_film());
            read.add(seconds_since(t));
            const double waited_before = writer.seconds_waited();
            writer.submit({std::move(image), open_output(folder.file("frame" + std::to_string(i) + ".exr")),
                           std::nullopt, "", "", false});
            wait.add(writer.seconds_waited() - waited_before);
        }
        const Clock::time_point t = Clock::now();
        writer.finish();
        bench.last_writes_ms = 1000.0 * seconds_since(t);
    }
    bench.loop_ms = 1000.0 * seconds_since(loop_start) / n;

    // 2. One frame's writing, step by step, alone (nothing renders, nothing
    // else is written): the film's way back, the denoiser, the encoding (its
    // blocks on every core) and the file. Memory is reused as the writer's is.
    const std::size_t alone = std::min<std::size_t>(jobs.size(), 4);
    {
        exr::ExrEncoding encoding;
        Film film;
        for (std::size_t i = 0; i < alone; ++i) {
            FinalImage image = image_of(plan, *renderer, write_options, std::move(film));
            Clock::time_point t = Clock::now();
            image.wait_for_film();
            arrive.add(seconds_since(t));
            t = Clock::now();
            image.encode(encoding);
            const double encoded = seconds_since(t);
            const double denoised = image.denoise_times ? image.denoise_times->seconds : 0.0;
            if (image.denoiser) denoise_phase.add(denoised);
            encode.add(encoded - denoised);
            bench.bytes_per_frame = encoding.bytes().size();
            const std::unique_ptr<ImageOutput> file = open_output(folder.file("alone.exr"));
            t = Clock::now();
            file->stage(encoding.bytes());
            stage.add(seconds_since(t));
            t = Clock::now();
            file->commit(encoding.bytes());
            place.add(seconds_since(t));
            film = std::move(image.film);
        }
    }
    bench.alone = plan.denoiser ? std::vector<FramesBenchmark::Phase>{arrive, denoise_phase, encode, stage, place}
                                : std::vector<FramesBenchmark::Phase>{arrive, encode, stage, place};

    // 3. The writer alone at 1, 2, 4, ... frames at once up to this run's:
    // the pace it keeps when nothing renders (the device's pace is the
    // render line above).
    bench.writer_frames = std::max<std::size_t>(jobs.size(), 2 * bench.in_flight);
    for (std::size_t count = 1;; count = std::min(2 * count, bench.in_flight)) {
        bench.writer_pace.push_back({count, writer_ms_per_frame(plan, *renderer, write_options, folder, open_output,
                                                                bench.writer_frames, count)});
        if (count == bench.in_flight) break;
    }

    bench.frames = jobs.size();
    bench.kernel_builds = renderer->programs_built();
    bench.overhead_ms = 1000.0 * (pose.total + upload.total + read.total + wait.total) / n;
    return bench;
}

void FramesBenchmark::Phase::add(double seconds) {
    total += seconds;
    most = std::max(most, seconds);
    ++count;
}

std::string FramesBenchmark::format(const std::vector<Phase>& phases) {
    std::string line;
    char text[160];
    for (const Phase& phase : phases) {
        std::snprintf(text, sizeof text, " %s %.1f (%.1f);", phase.name.c_str(), phase.mean_ms(), 1000.0 * phase.most);
        line += text;
    }
    return line;
}

std::string FramesBenchmark::writer_pace_text() const {
    std::string pace;
    char text[64];
    for (const auto& [count, ms] : writer_pace) {
        std::snprintf(text, sizeof text, "%s%zu: %.1f", pace.empty() ? "" : "; ", count, ms);
        pace += text;
    }
    return pace;
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
