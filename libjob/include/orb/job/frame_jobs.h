// The frames a render goes through (one job per output) and the shared
// renderer they use: orb-render's frame loop and its frames benchmark.
#pragma once

#include <functional>
#include <future>
#include <optional>
#include <string>
#include <vector>

#include "orb/exr/render_request.h"
#include "orb/job/messages.h"
#include "orb/job/render_plan.h"
#include "orb/render/renderer.h"

namespace orb::job {

struct Job {
    std::optional<long> frame;  // none for a render that is not a frame of an animation
    std::string output;
};

// "frame 12: ", or "" when the job is no frame.
std::string label_of(const Job& job);

// The jobs of a run: one per frame in the order given, its output named by
// `output_of` (orb-render: the -o pattern with the frame's number); without
// frames, the one output `still` of a render that is no frame.
std::vector<Job> jobs_of(const std::vector<long>& frames, const std::string& still,
                         const std::function<std::string(long frame)>& output_of);

// Poses the plan at the job's frame, unless it is posed there already.
void pose_for(RenderPlan& plan, const Job& job);

// Hands the plan's scene to the renderer when it changed since the last
// frame: the layout prepared ahead when there is one.
void upload_changed_scene(RenderPlan& plan, render::Renderer& renderer);

// Poses the plan at the job's frame (pose_for) and hands the scene and seed
// to the renderer, which is made on first use (one session and kernel build
// for every frame; `made` hears of it then); the film is emptied.
void set_up(RenderPlan& plan, const Job& job, std::optional<render::Renderer>& renderer,
            const std::function<void(render::Renderer&)>& made = {});

// What is at a job's output, against what the plan asks of it (the one
// definition of finished, orb::exr::judge_output). Every block is decoded:
// a frame skipped or continued by mistake costs more than reading it.
exr::OutputJudgement judge(RenderPlan& plan, const Job& job);

// The jobs whose outputs `judge` does not find finished, in order: what
// --skip-existing would render (orb-render --missing, orb-frames --missing).
// An output that is there but does not count (stopped short, damaged,
// another render) is noted, "frame 12: out.exr: why", to `notes`; an absent
// one is the usual case and says nothing new.
std::vector<Job> unfinished(const std::vector<Job>& jobs,
                            const std::function<exr::OutputJudgement(const Job&)>& judge, const MessageSink& notes);
// The same against what the plan asks, from the outputs' headers only (as
// orb-frames --missing reads them): --missing renders nothing, so it reads
// no pixels either.
std::vector<Job> unfinished(RenderPlan& plan, const std::vector<Job>& jobs);

// Loads the samples of `output` into the renderer, which set_up() left
// empty at the plan's first sample. Returns false, after saying why
// (plan.messages), when the file cannot be continued after all (changed
// since it was judged); the frame is then rendered from its first sample.
bool continue_from(RenderPlan& plan, const std::string& label, const std::string& output,
                   render::Renderer& renderer);

// The next frame's scene posed, hashed and laid out for the renderer (its
// BVH refitted or built) on another thread while this frame renders: for a
// million moving spheres that is seconds a frame.
class PosePrefetch {
public:
    // Starts posing `next`'s frame and laying it out for `renderer` (its
    // tree refitted or built), nothing for a scene that does not change
    // from frame to frame (no animation, no --orbit).
    void start(const RenderPlan& plan, const Job& next, render::Renderer& renderer);
    // Installs the prefetched pose when it is this job's frame; an error
    // posing it (a pose that breaks the scene limits) is thrown here.
    void use_for(RenderPlan& plan, const Job& job);

private:
    std::future<PosedFrame> future_;
    long frame_ = 0;
};

}  // namespace orb::job
