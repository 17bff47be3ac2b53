// The one definition of a finished output. A RenderRequest is what a command
// asks orb-render to put in one file; judge_output() compares what the file
// at that path holds (its header) with it. orb-render (--skip-existing,
// --claim, --missing), orb-frames --missing and orb-farm (through orb-render
// --missing) all decide with it, so they agree on every file.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "orb/exr/film_exr.h"
#include "orb/exr/render_status.h"

namespace orb::exr {

// The scene as rendered: its content hash (orb:sceneHash) and its camera
// (worldToCamera, worldToNDC at the image's size).
struct SceneIdentity {
    std::string hash;
    Matrix44 world_to_camera{};
    Matrix44 world_to_ndc{};
};

// Every field left empty is not compared: orb-frames without the scene
// cannot know its hash, its camera or the size it defaults to.
struct RenderRequest {
    // Asked for only when everything cheaper already matches: posing and
    // hashing a scene of millions of spheres takes seconds.
    std::function<SceneIdentity()> scene;
    std::optional<double> scene_time;
    std::optional<int> width, height;
    std::optional<std::string> mode;
    std::optional<std::string> sampler;
    std::optional<int> max_depth;
    std::optional<std::uint64_t> seed;  // the seed the image is rendered with (a frame's own, for frames)
    std::optional<std::vector<Pass>> passes;
    std::optional<bool> half;
    // The samples asked for. A whole frame (slice false) starts at sample 0
    // and is finished with at least `spp` of them; a slice (--sample-range)
    // must hold exactly [first_sample, first_sample + spp), since slices are
    // summed and must not overlap. Without `spp` a whole frame is finished
    // when it reached the target it was rendered toward (orb:targetSpp).
    bool slice = false;
    std::uint64_t first_sample = 0;
    std::optional<std::uint64_t> spp;
    // Adaptive sampling's settings asked for (none of either: a uniform
    // render); absent: not compared (orb-frames does not know them). A file
    // whose adaptive render ended on its rule (orb:adaptiveStop) before the
    // samples asked for is finished.
    struct Adaptive {
        std::optional<double> noise_threshold;
        std::optional<double> target_error;
    };
    std::optional<Adaptive> adaptive;
    // The kernels that would render it (orb:kernel, orb/render/kernel_identity.h):
    // a file another kernel rendered, or one that does not say, is another
    // render. Absent: not compared (orb-frames renders nothing).
    std::optional<std::string> kernel;
};

enum class OutputState {
    Missing,      // nothing at the path
    Finished,     // the render asked for: leave it alone
    Continuable,  // the render asked for, stopped short: continue it from its samples
    Different,    // another render, or damaged: render it again from its first sample
};

struct OutputJudgement {
    OutputState state = OutputState::Missing;
    // Why, for anything but Missing: "holds 16 of 64 spp", "rendered at
    // 320x240, 640x480 asked", "unreadable (truncated EXR ...)".
    std::string reason;
    std::uint64_t held_spp = 0;  // samples per pixel in the file
};

// Never throws for a bad file; a file it cannot read is Different. `check`
// says how closely to look for damage (render_status.h).
OutputJudgement judge_output(const std::string& path, const RenderRequest& request,
                             RenderCheck check = RenderCheck::Structure);

const char* state_name(OutputState state);

// Why a file of the kernels `file_kernel` (orb:kernel; empty: it does not
// say) is another render than one of `kernel`: "rendered by other kernels
// (orb:kernel 1f..., these are 9a...)".
std::string another_kernel(const std::string& file_kernel, const std::string& kernel);  // "missing", "finished", "partial", "different"

}  // namespace orb::exr
