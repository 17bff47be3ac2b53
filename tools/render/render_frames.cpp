#include "render_frames.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include <cerrno>
#include <cstring>

#include "command_line_plan.h"
#include "interrupt.h"
#include "orb/cli/folder_errors.h"
#include "orb/cli/frame_spec.h"
#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/cli/output_overlap.h"
#include "orb/cli/tool_main.h"
#include "orb/job/frame_run.h"
#include "orb/job/seconds_since.h"
#include "orb/scene/error.h"
#include "progress_reporter.h"

namespace orb::render_cli {
namespace {

// A missing or read-only folder fails at once, not at the first frame that
// is not skipped (outputs themselves are prepared frame by frame).
void require_output_folders(const std::vector<job::Job>& jobs) {
    std::vector<std::string> checked;
    for (const job::Job& job : jobs) {
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

// A frame's output, checked against the inputs and --stats-json as -o is for a still.
std::unique_ptr<job::ImageOutput> prepare_image(const std::string& path, const RenderOptions& options) {
    std::vector<cli::NamedPath> outputs{{"-o", path}};
    if (!options.stats_json.empty()) outputs.push_back({"--stats-json", options.stats_json});
    cli::refuse_overlapping_paths({{"SCENE", options.scene}}, outputs);
    return std::make_unique<OutputFileImage>(open_image_output(path, options));
}

}  // namespace

std::vector<job::Job> jobs_of(const job::RenderPlan& plan, const RenderOptions& options) {
    // With --frame N a name without a frame-number field is taken as it is.
    const bool pattern = cli::count_frame_fields(options.output) > 0;
    return job::jobs_of(plan.frames, options.output, [&](long frame) {
        return pattern ? cli::expand_frame_pattern(options.output, static_cast<int>(frame)) : options.output;
    });
}

void on_frames_renderer(render::Renderer& renderer) {
    cli::info(job::devices_line(renderer));
    install_interrupt_handlers();
}

int run_frames(job::RenderPlan& plan, const RenderOptions& options, RenderOutputs& outputs) {
    const std::vector<job::Job> jobs = jobs_of(plan, options);
    if (options.missing) {
        // What --skip-existing would render, without rendering (nor opening a device).
        std::string out;
        for (const job::Job& job : job::unfinished(plan, jobs))
            out += (job.frame ? std::to_string(*job.frame) : job.output) + "\n";
        return cli::print_to_stdout(out);
    }
    require_output_folders(jobs);
    const job::Clock::time_point start = job::Clock::now();

    ProgressReporter progress(cli::quiet(), options.time_limit.value_or(0), options.progress_interval);
    job::FrameRunOptions run_options;
    run_options.skip_existing = options.skip_existing;
    run_options.claim = options.claim;
    run_options.claim_stale_after = options.claim_stale_after;
    run_options.film = output_run(options, progress);
    job::FrameRunHooks hooks;
    hooks.prepare_output = [&](const job::Job& job) { return prepare_image(job.output, options); };
    hooks.summary = film_summary;
    hooks.renderer_made = on_frames_renderer;
    // A run killed while writing it left its lock, which no later run would take and release.
    hooks.skipped = [](const job::Job& job) { cli::OutputFile::remove_stale_lock(job.output); };
    const job::FramesRun run = job::run_frames(plan, jobs, run_options, hooks);
    if (run.stopped_before_image) {
        cli::error(*run.stopped_before_image + "interrupted before the first pass finished; no image written");
        return stopped_exit_code();
    }

    if (outputs.stats) outputs.stats->write(job::frames_run_stats_json(plan, run));
    if (interrupt_requested().load()) return stopped_exit_code();
    if (jobs.size() > 1)
        cli::info("frames: " + std::to_string(run.rendered.size()) + " rendered" +
                  (run.continued ? " (" + std::to_string(run.continued) + " continued)" : "") + ", " +
                  std::to_string(run.skipped.size()) + " finished already" +
                  (options.claim ? ", " + std::to_string(run.claimed_elsewhere) + " claimed elsewhere" : "") + " in " +
                  format_duration(job::seconds_since(start)) +
                  (run.kernel_builds ? " (" + job::kernel_builds_text(*run.kernel_builds) + ")" : "") +
                  (plan.trajectory ? "; " + std::to_string(plan.trajectory->frames_built()) + " frames read from " +
                                         plan.scene_label
                                   : ""));
    return cli::kSuccess;
}

}  // namespace orb::render_cli
