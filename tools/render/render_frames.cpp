#include "render_frames.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>

#include <cerrno>
#include <cstring>

#include "background_writer.h"
#include "frame_jobs.h"
#include "frame_claim.h"
#include "interrupt.h"
#include "orb/cli/folder_errors.h"
#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/cli/output_overlap.h"
#include "orb/cli/tool_main.h"
#include "orb/exr/film_exr.h"
#include "orb/exr/render_request.h"
#include "orb/scene/error.h"
#include "progress_reporter.h"
#include "render_film.h"
#include "seconds_since.h"

namespace orb::render_cli {
namespace {

// What is at a job's output, against what this run asks of it (the one
// definition of finished, orb::exr::judge_output). Every block is decoded:
// a frame skipped or continued by mistake costs more than reading it.
exr::OutputJudgement judge(RenderPlan& plan, const Job& job) {
    return exr::judge_output(job.output, request_for(plan, job.frame), exr::RenderCheck::Pixels);
}

// The one line saying what happens to an output that is there but is not
// the finished render asked for.
void announce(const std::string& label, const std::string& output, const exr::OutputJudgement& verdict) {
    if (verdict.state == exr::OutputState::Continuable)
        cli::info(label + output + ": " + verdict.reason + ": continuing it");
    else if (verdict.state == exr::OutputState::Different)
        cli::info(label + output + ": " + verdict.reason + ": rendering again");
}

// Loads the samples of `output` into the renderer, which set_up() left
// empty at the plan's first sample. Returns false, after saying why, when
// the file cannot be continued after all (changed since it was judged);
// the frame is then rendered from its first sample.
bool continue_from(RenderPlan& plan, const std::string& label, const std::string& output,
                   render::Renderer& renderer) {
    try {
        exr::ExrFilm file = exr::read_film_exr(output);
        exr::require_resumable(file, plan.passes, output);
        const SampleRanges& held = file.film.sample_ranges;
        if (held.ranges().size() != 1 || held.first() != plan.first_sample ||
            held.total() >= plan.target_spp)
            throw InputError(output + ": holds the samples " + held.format() + " now");
        renderer.load_film(file.film);
        if (!file.exact) cli::warning(label + output + ": " + exr::kMeansOnly);
        file.film = {};  // on the device now; the metadata stays for orb:renderSeconds
        plan.resumed = std::move(file);
        return true;
    } catch (const std::exception& e) {
        cli::warning(label + "cannot continue: " + e.what() + "; rendering it from its first sample");
        renderer.clear(plan.first_sample);
        return false;
    }
}

// --missing: what --skip-existing would render, without rendering (nor
// opening a device). Headers only, as orb-frames --missing reads them.
int list_missing(RenderPlan& plan, const std::vector<Job>& jobs) {
    std::string out;
    for (const Job& job : jobs) {
        const exr::OutputJudgement verdict = exr::judge_output(job.output, request_for(plan, job.frame));
        if (verdict.state == exr::OutputState::Finished) continue;
        if (verdict.state != exr::OutputState::Missing) cli::info(label_of(job) + job.output + ": " + verdict.reason);
        out += (job.frame ? std::to_string(*job.frame) : job.output) + "\n";
    }
    return cli::print_to_stdout(out);
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
        if (::access(folder.c_str(), W_OK | X_OK) != 0) {
            const int error = errno;
            std::string why = cli::unwritable_folder(folder, error);
            if (why.empty()) why = "folder " + folder + ": " + std::strerror(error);
            throw InputError(job.output + ": cannot write (-o): " + why);
        }
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
    if (options.missing) return list_missing(plan, jobs);
    require_output_folders(jobs);
    const bool finish_existing = options.skip_existing || options.claim;
    const Clock::time_point start = Clock::now();

    std::optional<render::Renderer> renderer;
    BackgroundWriter writer(std::max<std::size_t>(1, plan.frames_in_flight));  // after the renderer: destroyed first, so a pending write ends before it
    std::vector<RunStats> rendered;
    std::vector<std::shared_ptr<denoise::DenoiseTimes>> denoise_times;  // each rendered frame's, known once its write is done
    std::vector<long> skipped;
    int claimed_elsewhere = 0, continued = 0;
    PosePrefetch prefetch;
    for (std::size_t index = 0; index < jobs.size(); ++index) {
        const Job& job = jobs[index];
        if (interrupt_requested().load()) break;
        prefetch.use_for(plan, job);
        const std::string label = label_of(job);
        std::optional<exr::OutputJudgement> verdict;
        const auto finished = [&] {
            if (verdict->state != exr::OutputState::Finished) return false;
            cli::info(label + job.output + ": finished (" + std::to_string(verdict->held_spp) + " spp); skipped");
            if (job.frame) skipped.push_back(*job.frame);
            // A run killed while writing it left its lock, which no later run would take and release.
            cli::OutputFile::remove_stale_lock(job.output);
            return true;
        };
        if (finish_existing) {
            verdict = judge(plan, job);
            if (finished()) continue;
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
            // Another machine may have finished or continued it between the check and the claim.
            verdict = judge(plan, job);
            if (finished()) continue;
        }
        if (verdict) announce(label, job.output, *verdict);

        cli::OutputFile image = prepare_image(job.output, options);
        set_up(plan, job, renderer);
        plan.resumed.reset();
        if (verdict && verdict->state == exr::OutputState::Continuable &&
            continue_from(plan, label, job.output, *renderer))
            ++continued;
        if (index + 1 < jobs.size()) prefetch.start(plan, jobs[index + 1], *renderer);
        FilmOutcome outcome = render_film(*renderer, plan, options, image, label, claim ? &*claim : nullptr,
                                          writer.take_spare_film(), /*read_later=*/true);
        if (!outcome.rendered) {
            writer.finish();
            cli::error(label + "interrupted before the first pass finished; no image written");
            return interrupt_exit_code() ? interrupt_exit_code() : cli::kFailure;
        }
        rendered.push_back(outcome.stats);
        denoise_times.push_back(outcome.image.denoise_times);
        const std::string summary = film_summary(outcome, *renderer, image);
        const bool interrupted = outcome.reason == render::StopReason::Interrupted;
        const std::string written = interrupted ? "interrupted: wrote " + summary
                                    : outcome.reason == render::StopReason::ReachedTime ? "time limit reached: " + summary
                                                                                       : "done: " + summary;
        // Written while the next frame renders, which says so once its file
        // is in place; a failed write ends the run at the next frame.
        writer.submit({std::move(outcome.image), std::move(image), std::move(claim), label, written, interrupted});
        if (interrupted) break;
    }
    writer.finish();
    for (std::size_t i = 0; i < rendered.size(); ++i)
        if (denoise_times[i]) rendered[i].denoise = *denoise_times[i];

    if (outputs.stats)
        outputs.stats->write(plan.frames.size() > 1 || rendered.empty() ? frames_stats_json(rendered, skipped)
                                                                        : stats_json(rendered.front()));
    if (interrupt_requested().load()) return interrupt_exit_code() ? interrupt_exit_code() : cli::kFailure;
    if (jobs.size() > 1)
        cli::info("frames: " + std::to_string(rendered.size()) + " rendered" +
                  (continued ? " (" + std::to_string(continued) + " continued)" : "") + ", " +
                  std::to_string(skipped.size()) + " finished already" +
                  (options.claim ? ", " + std::to_string(claimed_elsewhere) + " claimed elsewhere" : "") + " in " +
                  format_duration(seconds_since(start)) +
                  (renderer ? " (" + kernel_builds_text(renderer->programs_built()) + ")" : "") +
                  (plan.trajectory ? "; " + std::to_string(plan.trajectory->frames_built()) + " frames read from " +
                                         plan.scene_label
                                   : ""));
    return cli::kSuccess;
}

}  // namespace orb::render_cli
