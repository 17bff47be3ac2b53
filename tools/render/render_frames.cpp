#include "render_frames.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "background_writer.h"
#include "frame_claim.h"
#include "interrupt.h"
#include "orb/cli/frame_spec.h"
#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/cli/output_overlap.h"
#include "orb/cli/tool_main.h"
#include "orb/exr/film_exr.h"
#include "orb/exr/render_status.h"
#include "orb/scene/error.h"
#include "progress_reporter.h"
#include "render_film.h"

namespace orb::render_cli {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct Job {
    std::optional<long> frame;
    std::string output;
};

// With --frame N, an output without a frame number (or with a '%' that is
// not one) is a plain name; with several frames the options check already
// required a frame number.
bool has_frame_number(const std::string& output) {
    try {
        return cli::count_frame_fields(output) > 0;
    } catch (const cli::UsageError&) {
        return false;
    }
}

std::vector<Job> jobs_of(const RenderPlan& plan, const RenderOptions& options) {
    if (plan.frames.empty()) return {Job{std::nullopt, options.output}};
    const bool pattern = has_frame_number(options.output);
    std::vector<Job> jobs;
    for (long frame : plan.frames)
        jobs.push_back(
            {frame, pattern ? cli::expand_frame_pattern(options.output, static_cast<int>(frame)) : options.output});
    return jobs;
}

std::string label_of(const Job& job) { return job.frame ? "frame " + std::to_string(*job.frame) + ": " : ""; }

// Why `path` is not a finished render, or nothing when it is one (the one
// definition of finished, orb::exr::inspect_render; every block decoded,
// since a frame skipped by mistake costs more than reading it).
std::optional<std::string> unfinished(const std::string& path) {
    const exr::RenderStatus status = exr::inspect_render(path, exr::RenderCheck::Pixels);
    if (status.complete) return std::nullopt;
    if (!status.exists) return "it does not exist";
    if (!status.readable) return "it is unreadable (" + path + ": " + status.reason + ")";
    return "it holds " + std::to_string(status.spp) + " of its " + std::to_string(status.target_spp) + " spp";
}

// A missing or read-only folder fails at once, not at the first frame that
// is not skipped (outputs themselves are prepared frame by frame).
void require_output_folders(const std::vector<Job>& jobs) {
    std::vector<std::string> checked;
    for (const Job& job : jobs) {
        if (cli::is_stdio(job.output)) continue;
        std::string folder = std::filesystem::path(job.output).parent_path().string();
        if (folder.empty()) folder = ".";
        if (std::find(checked.begin(), checked.end(), folder) != checked.end()) continue;
        checked.push_back(folder);
        std::error_code ec;
        if (!std::filesystem::is_directory(folder, ec))
            throw InputError(job.output + ": cannot write (-o): folder " + folder + " does not exist");
        if (::access(folder.c_str(), W_OK | X_OK) != 0)
            throw InputError(job.output + ": cannot write (-o): folder " + folder + " is not writable");
        if (checked.size() > 16) break;  // a pattern with the frame in the folder: the first few tell
    }
}

cli::OutputFile prepare_image(const std::string& path, const RenderOptions& options) {
    std::vector<cli::NamedPath> outputs{{"-o", path}};
    if (!options.stats_json.empty()) outputs.push_back({"--stats-json", options.stats_json});
    cli::refuse_overlapping_paths({{"SCENE", options.scene}}, outputs);
    cli::OutputFile image(path, "-o");
    if (options.checkpoint && image.kind() == cli::OutputFile::Kind::Stream)
        throw cli::UsageError("--checkpoint rewrites the output while rendering, but -o " + path + " is " +
                              image.stream_description() + "; drop --checkpoint");
    return image;
}

// Poses the plan at the job's frame (unless it is posed there already) and
// hands the scene and seed to the renderer, which is made on first use.
void set_up(RenderPlan& plan, const Job& job, std::optional<render::Renderer>& renderer) {
    if (job.frame && (!plan.frame || plan.frame->number != *job.frame)) pose_frame(plan, *job.frame);
    if (!renderer) {
        renderer.emplace(plan.scene, plan.config);
        cli::info("device: " + device_label(renderer->device()));
        // From here on a signal ends the frame in flight gracefully; before,
        // during the kernel build, there is nothing to save.
        install_interrupt_handlers();
    } else {
        renderer->set_scene(plan.scene);
        renderer->set_seed(plan.config.seed);
    }
    renderer->clear(plan.first_sample);
}

}  // namespace

int run_frames(RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs) {
    const std::vector<Job> jobs = jobs_of(plan, options);
    require_output_folders(jobs);
    const bool skip_complete = options.skip_existing || options.claim;
    const Clock::time_point start = Clock::now();

    std::optional<render::Renderer> renderer;
    BackgroundWriter writer;  // after the renderer: destroyed first, so a pending write ends before it
    std::vector<RunStats> rendered;
    std::vector<long> skipped;
    int claimed_elsewhere = 0;
    for (const Job& job : jobs) {
        if (interrupt_requested().load()) break;
        const std::string label = label_of(job);
        if (skip_complete) {
            if (!unfinished(job.output)) {
                cli::info(label + job.output + " is complete; skipped");
                if (job.frame) skipped.push_back(*job.frame);
                continue;
            }
        }
        std::optional<FrameClaim> claim;
        if (options.claim) {
            std::string holder;
            claim = FrameClaim::acquire(job.output, options.claim_stale_after, holder);
            if (!claim) {
                cli::info(label + job.output + " is claimed by " + holder + "; skipped");
                ++claimed_elsewhere;
                continue;
            }
            // Another machine may have finished it between the check and the claim.
            if (!unfinished(job.output)) {
                cli::info(label + job.output + " is complete; skipped");
                if (job.frame) skipped.push_back(*job.frame);
                continue;
            }
        } else if (skip_complete) {
            if (const auto why = unfinished(job.output); why && *why != "it does not exist")
                cli::info(label + "rendering " + job.output + " again: " + *why);
        }

        cli::OutputFile image = prepare_image(job.output, options);
        set_up(plan, job, renderer);
        FilmOutcome outcome = render_film(*renderer, plan, options, image, label, claim ? &*claim : nullptr,
                                          writer.take_spare_film());
        if (!outcome.rendered) {
            writer.finish();
            cli::error(label + "interrupted before the first pass finished; no image written");
            return interrupt_exit_code() ? interrupt_exit_code() : cli::kFailure;
        }
        rendered.push_back(outcome.stats);
        const std::string summary = film_summary(outcome, *renderer, image);
        // Written while the next frame renders; a failed write ends the run at the next frame.
        writer.submit({std::move(outcome.image), std::move(image), std::move(claim)});
        if (outcome.reason == render::StopReason::Interrupted) {
            cli::warning(label + "interrupted: wrote " + summary);
            break;
        }
        cli::info(label + (outcome.reason == render::StopReason::ReachedTime ? "time limit reached: " : "done: ") +
                  summary);
    }
    writer.finish();

    if (outputs.stats)
        outputs.stats->write(plan.frames.size() > 1 || rendered.empty() ? frames_stats_json(rendered, skipped)
                                                                        : stats_json(rendered.front()));
    if (interrupt_requested().load()) return interrupt_exit_code() ? interrupt_exit_code() : cli::kFailure;
    if (jobs.size() > 1)
        cli::info("frames: " + std::to_string(rendered.size()) + " rendered, " + std::to_string(skipped.size()) +
                  " complete already" +
                  (options.claim ? ", " + std::to_string(claimed_elsewhere) + " claimed elsewhere" : "") + " in " +
                  format_duration(seconds_since(start)) +
                  (renderer ? " (" + std::to_string(renderer->programs_built()) + " kernel build)" : ""));
    return cli::kSuccess;
}

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
        encode{"encode+write (beside rendering)"};
    exr::ExrWriteOptions write_options;
    write_options.passes = plan.passes;
    write_options.half = plan.half;
    try {
        BackgroundWriter writer;
        for (std::size_t i = 0; i < jobs.size(); ++i) {
            const Job& job = jobs[i];
            Clock::time_point t = Clock::now();
            if (job.frame) pose_frame(plan, *job.frame);
            pose.add(seconds_since(t));
            t = Clock::now();
            renderer->set_scene(plan.scene);
            renderer->set_seed(plan.config.seed);
            renderer->clear(plan.first_sample);
            upload.add(seconds_since(t));
            t = Clock::now();
            for (int done = 0; done < spp;) {
                const int pass = std::min(spp - done, std::max(1, renderer->suggested_samples_per_pass()));
                renderer->render_pass(pass);
                done += pass;
            }
            render_phase.add(seconds_since(t));
            t = Clock::now();
            FinalImage image{writer.take_spare_film(), plan_metadata(plan), write_options};
            renderer->read_film(image.film);
            read.add(seconds_since(t));
            const double waited_before = writer.seconds_waited();
            writer.submit({std::move(image), cli::OutputFile(folder + "/frame" + std::to_string(i) + ".exr", "-o"),
                           std::nullopt});
            wait.add(writer.seconds_waited() - waited_before);
        }
        writer.finish();
        // The writer's own time, measured apart from rendering: one frame encoded and written alone.
        for (std::size_t i = 0; i < std::min<std::size_t>(jobs.size(), 4); ++i) {
            const Clock::time_point t = Clock::now();
            FinalImage image{renderer->read_film(), plan_metadata(plan), write_options};
            cli::OutputFile(folder + "/alone.exr", "-o").write(image.encode());
            encode.add(seconds_since(t));
        }
        encode.total *= static_cast<double>(jobs.size()) / static_cast<double>(std::min<std::size_t>(jobs.size(), 4));
    } catch (...) {
        std::filesystem::remove_all(folder);
        throw;
    }
    std::filesystem::remove_all(folder);

    const double n = static_cast<double>(jobs.size());
    const double overhead_ms = 1000.0 * (pose.total + upload.total + read.total + wait.total) / n;
    std::string line = "frames benchmark: " + std::to_string(jobs.size()) + " frames at " +
                       std::to_string(plan.config.width) + "x" + std::to_string(plan.config.height) + ", " +
                       std::to_string(renderer->programs_built()) + " kernel build; per frame, mean (max) ms:";
    char text[128];
    for (const Phase* phase : {&pose, &upload, &render_phase, &read, &wait, &encode}) {
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
