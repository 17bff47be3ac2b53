#include "render_frames.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>

#include "background_writer.h"
#include "frame_jobs.h"
#include "frame_claim.h"
#include "interrupt.h"
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
                  (renderer ? " (" + kernel_builds_text(renderer->programs_built()) + ")" : ""));
    return cli::kSuccess;
}

}  // namespace orb::render_cli
