#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "background_writer.h"
#include "frame_jobs.h"
#include "orb/cli/messages.h"
#include "orb/cli/output_file.h"
#include "orb/cli/tool_main.h"
#include "orb/scene/error.h"
#include "render_film.h"
#include "seconds_since.h"
#include "render_frames.h"

namespace orb::render_cli {

int run_frames_benchmark(RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs) {
    (void)outputs;
    const std::vector<Job> jobs = jobs_of(plan, options);
    std::optional<render::Renderer> renderer;
    // The first frame pays for the kernel build and the driver's lazy set-up:
    // rendered once before timing.
    set_up(plan, jobs.front(), renderer);
    renderer->render_pass(1);

    // The EXRs are written as real frames are (on the writer's thread, to a
    // temporary file that is flushed and renamed), into a private folder
    // that is removed afterwards.
    const char* tmp = std::getenv("TMPDIR");
    std::string folder = std::string(tmp && *tmp ? tmp : "/tmp") + "/orb-frames-benchmark-XXXXXX";
    if (!::mkdtemp(folder.data())) throw InputError(folder + ": cannot make a folder for the benchmark's frames");

    struct Phase {
        const char* name;
        double total = 0, most = 0;
        void add(double seconds) {
            total += seconds;
            most = std::max(most, seconds);
        }
    };
    // Samples per frame: --spp, else 1. With fewer samples than it takes to
    // write a frame, the writer's time shows as waiting.
    const int spp = static_cast<int>(options.spp.value_or(1));
    const std::string render_name = "render (" + std::to_string(spp) + " spp)";
    Phase pose{"pose"}, upload{"upload"}, render_phase{render_name.c_str()}, read{"read back"}, wait{"wait for writer"},
        encode{"alone: encode"}, write{"alone: write+fsync"};
    exr::ExrWriteOptions write_options;
    write_options.passes = plan.passes;
    write_options.half = plan.half;
    write_options.compression = plan.compression;
    std::size_t bytes_per_frame = 0;
    try {
        PosePrefetch prefetch;
        BackgroundWriter writer;
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
            image.arriving = renderer->read_film_later();
            read.add(seconds_since(t));
            const double waited_before = writer.seconds_waited();
            writer.submit({std::move(image), cli::OutputFile(folder + "/frame" + std::to_string(i) + ".exr", "-o"),
                           std::nullopt, "", "", false});
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
            Clock::time_point t = Clock::now();
            image.encode(encoding);
            encode.add(seconds_since(t));
            bytes_per_frame = encoding.bytes().size();
            t = Clock::now();
            cli::OutputFile(folder + "/alone.exr", "-o").write(encoding.bytes());
            write.add(seconds_since(t));
        }
        for (Phase* phase : {&encode, &write}) phase->total *= static_cast<double>(jobs.size()) / static_cast<double>(alone);
    } catch (...) {
        std::filesystem::remove_all(folder);
        throw;
    }
    std::filesystem::remove_all(folder);

    const double n = static_cast<double>(jobs.size());
    const double overhead_ms = 1000.0 * (pose.total + upload.total + read.total + wait.total) / n;
    std::string line = "frames benchmark: " + std::to_string(jobs.size()) + " frames at " +
                       std::to_string(plan.config.width) + "x" + std::to_string(plan.config.height) + ", layers " +
                       exr::format_passes(plan.passes) + (plan.half ? " (half)" : "") + ", " +
                       exr::compression_name(plan.compression) + " " + std::to_string(bytes_per_frame / 1000) +
                       " kB a frame, " + kernel_builds_text(renderer->programs_built()) +
                       "; per frame, mean (max) ms:";
    char text[128];
    for (const Phase* phase : {&pose, &upload, &render_phase, &read, &wait, &encode, &write}) {
        std::snprintf(text, sizeof text, " %s %.1f (%.1f);", phase->name, 1000.0 * phase->total / n,
                      1000.0 * phase->most);
        line += text;
    }
    cli::info(line);
    // The time a frame adds to the render path besides its samples.
    std::printf("frame_overhead_ms=%.1f\n", overhead_ms);
    std::fflush(stdout);
    return cli::kSuccess;
}

}  // namespace orb::render_cli
