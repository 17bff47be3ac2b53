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
namespace {

struct Phase {
    std::string name;
    double total = 0, most = 0;
    int count = 0;
    void add(double seconds) {
        total += seconds;
        most = std::max(most, seconds);
        ++count;
    }
    double mean_ms() const { return count ? 1000.0 * total / count : 0.0; }
};

// " name mean (max);" for each phase, in milliseconds.
std::string format_phases(std::initializer_list<const Phase*> phases) {
    std::string line;
    char text[160];
    for (const Phase* phase : phases) {
        std::snprintf(text, sizeof text, " %s %.1f (%.1f);", phase->name.c_str(), phase->mean_ms(), 1000.0 * phase->most);
        line += text;
    }
    return line;
}

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

// The final image of the film on the device, as a frame's is: read back
// while the caller goes on, with the denoised layer when --denoise.
FinalImage image_of(const RenderPlan& plan, render::Renderer& renderer, const exr::ExrWriteOptions& options,
                    Film reuse) {
    FinalImage image{std::move(reuse), plan_metadata(plan), options, std::nullopt};
    image.arriving = renderer.read_film_later();
    image.denoiser = plan.denoiser;
    if (plan.denoiser) image.denoise_times = std::make_shared<denoise::DenoiseTimes>();
    return image;
}

// The writer alone: `frames` frames of the film on the device read back and
// written through a BackgroundWriter of `in_flight` frames, as fast as it
// takes them. Returns milliseconds a frame.
double writer_ms_per_frame(const RenderPlan& plan, render::Renderer& renderer, const exr::ExrWriteOptions& options,
                           const ScratchFolder& folder, std::size_t frames, std::size_t in_flight) {
    const Clock::time_point start = Clock::now();
    BackgroundWriter writer(in_flight);
    for (std::size_t i = 0; i < frames; ++i)
        writer.submit({image_of(plan, renderer, options, writer.take_spare_film()),
                       cli::OutputFile(folder.file("writer" + std::to_string(i) + ".exr"), "-o"), std::nullopt, "",
                       "", false});
    writer.finish();
    return 1000.0 * seconds_since(start) / static_cast<double>(frames);
}

}  // namespace

int run_frames_benchmark(RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs) {
    (void)outputs;
    const std::vector<Job> jobs = jobs_of(plan, options);
    std::optional<render::Renderer> renderer;
    // The first frame pays for the kernel build and the driver's lazy set-up:
    // rendered once before timing.
    set_up(plan, jobs.front(), renderer);
    renderer->render_pass(1);

    // The EXRs are written as real frames are (on the writer's threads, to
    // temporary files that are flushed and renamed), into a private folder.
    const ScratchFolder folder;

    // Samples per frame: --spp, else 1. With fewer samples than it takes to
    // write a frame, the writer's time shows as waiting.
    const int spp = static_cast<int>(options.spp.value_or(1));
    Phase pose{"pose"}, upload{"upload"}, render_phase{"render (" + std::to_string(spp) + " spp)"},
        read{"read back (started)"}, wait{"wait for writer"};
    Phase arrive{"read back"}, denoise_phase{"denoise"}, encode{"encode"}, stage{"write+fsync"}, place{"rename"};
    exr::ExrWriteOptions write_options;
    write_options.passes = plan.passes;
    write_options.half = plan.half;
    write_options.compression = plan.compression;
    const std::size_t in_flight = std::max<std::size_t>(1, plan.frames_in_flight);
    const double n = static_cast<double>(jobs.size());

    // 1. The frame loop as a real run goes through it: what each frame adds
    // to the render path besides its samples, and the loop's own pace.
    const Clock::time_point loop_start = Clock::now();
    double last_writes_ms = 0;  // the frames still being written once the last has rendered
    {
        PosePrefetch prefetch;
        BackgroundWriter writer(in_flight);
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
            writer.submit({std::move(image), cli::OutputFile(folder.file("frame" + std::to_string(i) + ".exr"), "-o"),
                           std::nullopt, "", "", false});
            wait.add(writer.seconds_waited() - waited_before);
        }
        const Clock::time_point t = Clock::now();
        writer.finish();
        last_writes_ms = 1000.0 * seconds_since(t);
    }
    const double loop_ms = 1000.0 * seconds_since(loop_start) / n;

    // 2. One frame's writing, step by step, alone (nothing renders, nothing
    // else is written): the film's way back, the denoiser, the encoding (its
    // blocks on every core) and the file. Memory is reused as the writer's is.
    const std::size_t alone = std::min<std::size_t>(jobs.size(), 4);
    std::size_t bytes_per_frame = 0;
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
            bytes_per_frame = encoding.bytes().size();
            cli::OutputFile file(folder.file("alone.exr"), "-o");
            t = Clock::now();
            file.stage(encoding.bytes());
            stage.add(seconds_since(t));
            t = Clock::now();
            file.commit(encoding.bytes());
            place.add(seconds_since(t));
            film = std::move(image.film);
        }
    }

    // 3. The writer alone at 1, 2, 4, ... frames at once up to this run's:
    // the pace it keeps when nothing renders (the device's pace is the
    // render line above).
    std::string pace;
    char text[96];
    const std::size_t frames = std::max<std::size_t>(jobs.size(), 2 * in_flight);
    for (std::size_t count = 1;; count = std::min(2 * count, in_flight)) {
        std::snprintf(text, sizeof text, "%s%zu: %.1f", pace.empty() ? "" : "; ", count,
                      writer_ms_per_frame(plan, *renderer, write_options, folder, frames, count));
        pace += text;
        if (count == in_flight) break;
    }

    const double overhead_ms = 1000.0 * (pose.total + upload.total + read.total + wait.total) / n;
    std::snprintf(text, sizeof text, " then the last writes %.1f ms; the loop %.1f ms a frame;", last_writes_ms,
                  loop_ms);
    cli::info("frames benchmark: " + std::to_string(jobs.size()) + " frames at " + std::to_string(plan.config.width) +
              "x" + std::to_string(plan.config.height) + ", layers " + exr::format_passes(plan.passes) +
              (plan.half ? " (half)" : "") + ", " + exr::compression_name(plan.compression) + " " +
              std::to_string(bytes_per_frame / 1000) + " kB a frame, " +
              kernel_builds_text(renderer->programs_built()) + ", " + std::to_string(in_flight) +
              " frames written at once; per frame, mean (max) ms:" +
              format_phases({&pose, &upload, &render_phase, &read, &wait}) + text);
    cli::info("frames benchmark: one frame written alone, mean (max) ms:" +
              format_phases(plan.denoiser ? std::initializer_list<const Phase*>{&arrive, &denoise_phase, &encode, &stage, &place}
                                          : std::initializer_list<const Phase*>{&arrive, &encode, &stage, &place}));
    cli::info("frames benchmark: the writer alone, " + std::to_string(frames) +
              " frames, ms a frame with N frames written at once (N: ms): " + pace);
    // The time a frame adds to the render path besides its samples.
    std::printf("frame_overhead_ms=%.1f\n", overhead_ms);
    std::fflush(stdout);
    return cli::kSuccess;
}

}  // namespace orb::render_cli
