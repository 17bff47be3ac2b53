#include "orb/job/frame_jobs.h"

#include "orb/exr/film_exr.h"
#include "orb/scene/error.h"

namespace orb::job {

std::string label_of(const Job& job) { return job.frame ? "frame " + std::to_string(*job.frame) + ": " : ""; }

std::vector<Job> jobs_of(const std::vector<long>& frames, const std::string& still,
                         const std::function<std::string(long frame)>& output_of) {
    if (frames.empty()) return {Job{std::nullopt, still}};
    std::vector<Job> jobs;
    for (long frame : frames) jobs.push_back({frame, output_of(frame)});
    return jobs;
}

void pose_for(RenderPlan& plan, const Job& job) {
    if (job.frame && !posed_at(plan, *job.frame)) pose_frame(plan, *job.frame);
}

void upload_changed_scene(RenderPlan& plan, render::Renderer& renderer) {
    if (plan.scene_changed) {
        if (plan.prepared_scene)
            renderer.set_scene(std::move(*plan.prepared_scene));
        else
            renderer.set_scene(plan.scene);
    }
    plan.scene_changed = false;
    plan.prepared_scene.reset();
}

void set_up(RenderPlan& plan, const Job& job, std::optional<render::Renderer>& renderer,
            const std::function<void(render::Renderer&)>& made) {
    pose_for(plan, job);
    if (!renderer) {
        renderer.emplace(plan.scene, plan.config);
        if (made) made(*renderer);
        plan.scene_changed = false;  // the renderer was made with it
        plan.prepared_scene.reset();
    } else {
        upload_changed_scene(plan, *renderer);
        renderer->set_seed(plan.config.seed);
    }
    renderer->clear(plan.first_sample);
}

void PosePrefetch::start(const RenderPlan& plan, const Job& next, render::Renderer& renderer) {
    if (!next.frame || !changes_per_frame(plan)) return;
    frame_ = *next.frame;
    future_ = std::async(std::launch::async, [&plan, &renderer, frame = frame_] {
        PosedFrame posed = pose_at(plan, frame);
        if (posed.scene) posed.prepared = renderer.prepare_scene(*posed.scene);
        return posed;
    });
}

void PosePrefetch::use_for(RenderPlan& plan, const Job& job) {
    if (!future_.valid()) return;
    PosedFrame posed = future_.get();
    if (job.frame && *job.frame == frame_ && !posed_at(plan, frame_)) install(plan, std::move(posed));
}

exr::OutputJudgement judge(RenderPlan& plan, const Job& job) {
    return exr::judge_output(job.output, request_for(plan, job.frame), exr::RenderCheck::Pixels);
}

std::vector<Job> unfinished(const std::vector<Job>& jobs,
                            const std::function<exr::OutputJudgement(const Job&)>& judge, const MessageSink& notes) {
    std::vector<Job> left;
    for (const Job& job : jobs) {
        const exr::OutputJudgement verdict = judge(job);
        if (verdict.state == exr::OutputState::Finished) continue;
        if (verdict.state != exr::OutputState::Missing)
            say(notes, MessageKind::Info, label_of(job) + job.output + ": " + verdict.reason);
        left.push_back(job);
    }
    return left;
}

std::vector<Job> unfinished(RenderPlan& plan, const std::vector<Job>& jobs) {
    return unfinished(
        jobs, [&](const Job& job) { return exr::judge_output(job.output, request_for(plan, job.frame)); },
        plan.messages);
}

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
        if (!file.exact) say(plan.messages, MessageKind::Warning, label + output + ": " + exr::kMeansOnly);
        file.film = {};  // on the device now; the metadata stays for orb:renderSeconds
        plan.resumed = std::move(file);
        plan.resumed_path = output;
        return true;
    } catch (const std::exception& e) {
        say(plan.messages, MessageKind::Warning,
            label + "cannot continue: " + e.what() + "; rendering it from its first sample");
        renderer.clear(plan.first_sample);
        return false;
    }
}

}  // namespace orb::job
