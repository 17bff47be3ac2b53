#include "render_frames.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include <cerrno>
#include <cstring>

#include "film_output.h"
#include "orb/job/frame_run.h"
#include "interrupt.h"
#include "orb/cli/folder_errors.h"
#include "orb/cli/frame_spec.h"
#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/cli/output_overlap.h"
#include "orb/cli/tool_main.h"
#include "orb/exr/render_request.h"
#include "orb/scene/error.h"
#include "progress_reporter.h"

namespace orb::render_cli {
namespace {

// --missing: what --skip-existing would render, without rendering (nor
// opening a device). Headers only, as orb-frames --missing reads them.
int list_missing(RenderPlan& plan, const std::vector<Job>& jobs) {
    std::string out;
    for (const Job& job : jobs) {
        const exr::OutputJudgement verdict = exr::judge_output(job.output, job::request_for(plan, job.frame));
        if (verdict.state == exr::OutputState::Finished) continue;
        if (verdict.state != exr::OutputState::Missing) cli::info(job::label_of(job) + job.output + ": " + verdict.reason);
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

std::vector<Job> jobs_of(const RenderPlan& plan, const RenderOptions& options) {
    if (plan.frames.empty()) return {Job{std::nullopt, options.output}};
    // With --frame N a name without a frame-number field is taken as it is.
    const bool pattern = cli::count_frame_fields(options.output) > 0;
    std::vector<Job> jobs;
    for (long frame : plan.frames)
        jobs.push_back(
            {frame, pattern ? cli::expand_frame_pattern(options.output, static_cast<int>(frame)) : options.output});
    return jobs;
}

void on_frames_renderer(render::Renderer& renderer) {
    cli::info(job::devices_line(renderer));
    install_interrupt_handlers();
}

int run_frames(RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs) {
    const std::vector<Job> jobs = jobs_of(plan, options);
    if (options.missing) return list_missing(plan, jobs);
    require_output_folders(jobs);
    const Clock::time_point start = Clock::now();

    job::FrameRunOptions run_options;
    run_options.skip_existing = options.skip_existing;
    run_options.claim = options.claim;
    run_options.claim_stale_after = options.claim_stale_after;
    run_options.cancel = &interrupt_requested();
    job::FrameRunHooks hooks;
    hooks.prepare_output = [&](const Job& job) {
        return std::make_unique<OutputFileImage>(prepare_image(job.output, options));
    };
    hooks.render = [&](render::Renderer& renderer, const RenderPlan& posed, job::ImageOutput& output,
                       const std::string& label, FrameClaim* claim, Film reuse) {
        return render_film(renderer, posed, options, output, label, claim, std::move(reuse), /*read_later=*/true);
    };
    hooks.summary = film_summary;
    hooks.renderer_made = on_frames_renderer;
    // A run killed while writing it left its lock, which no later run would take and release.
    hooks.skipped = [](const Job& job) { cli::OutputFile::remove_stale_lock(job.output); };
    const job::FramesRun run = job::run_frames(plan, jobs, run_options, hooks);
    if (run.stopped_before_image) {
        cli::error(*run.stopped_before_image + "interrupted before the first pass finished; no image written");
        return interrupt_exit_code() ? interrupt_exit_code() : cli::kFailure;
    }

    if (outputs.stats)
        outputs.stats->write(plan.frames.size() > 1 || run.rendered.empty() ? job::frames_stats_json(run.rendered, run.skipped)
                                                                            : job::stats_json(run.rendered.front()));
    if (interrupt_requested().load()) return interrupt_exit_code() ? interrupt_exit_code() : cli::kFailure;
    if (jobs.size() > 1)
        cli::info("frames: " + std::to_string(run.rendered.size()) + " rendered" +
                  (run.continued ? " (" + std::to_string(run.continued) + " continued)" : "") + ", " +
                  std::to_string(run.skipped.size()) + " finished already" +
                  (options.claim ? ", " + std::to_string(run.claimed_elsewhere) + " claimed elsewhere" : "") + " in " +
                  format_duration(seconds_since(start)) +
                  (run.kernel_builds ? " (" + job::kernel_builds_text(*run.kernel_builds) + ")" : "") +
                  (plan.trajectory ? "; " + std::to_string(plan.trajectory->frames_built()) + " frames read from " +
                                         plan.scene_label
                                   : ""));
    return cli::kSuccess;
}

}  // namespace orb::render_cli
