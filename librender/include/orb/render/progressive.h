// Progressive rendering: passes until a sample or time budget is reached,
// with periodic checkpoints and a clean stop on request (SIGINT/SIGTERM).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>

#include "orb/render/pass_renderer.h"

namespace orb::render {

enum class StopReason {
    ReachedSpp,
    ReachedTime,
    Interrupted,
    Converged,    // adaptive sampling: every pixel's error is below the noise threshold
    ReachedError  // adaptive sampling: the frame's estimated error is below the target
};

// What adaptive sampling (adaptive_sampler.h) adds to the loop: decisions at
// fixed sample counts, which passes end at, each of which may end the render.
class PassGate {
public:
    virtual ~PassGate() = default;
    // The film's samples per pixel at the first decision after `spp`.
    virtual std::uint64_t next_decision(std::uint64_t spp) const = 0;
    // After a pass that brought the film to a decision's sample count.
    virtual void decide() = 0;
    // Why the render is done, if it is.
    virtual std::optional<StopReason> stop() const = 0;
};

struct ProgressiveLimits {
    std::uint64_t target_spp = 64;   // total samples per pixel, counting resumed ones
    double max_seconds = 0;          // 0 = no time limit
    double checkpoint_seconds = 0;   // 0 = no checkpoints by time
    int checkpoint_passes = 0;       // > 0: a checkpoint every this many passes instead (a live preview's pace)
    PassGate* gate = nullptr;        // adaptive sampling, or none
};

struct ProgressState {
    int pass = 0;
    std::uint64_t spp = 0;
    std::uint64_t target_spp = 0;
    double elapsed_seconds = 0;
    double samples_per_second = 0;  // pixel samples per second over this run (those drawn: adaptive sampling skips pixels)
};

struct ProgressiveCallbacks {
    std::function<void(const ProgressState&)> on_pass;        // after every pass
    std::function<void(const ProgressState&)> on_checkpoint;  // when a checkpoint is due
};

// Renders until a limit is reached or `stop_requested` becomes true (checked
// between passes, so the pass in flight always completes).
StopReason render_progressively(PassRenderer& renderer, const ProgressiveLimits& limits,
                                const ProgressiveCallbacks& callbacks, const std::atomic<bool>& stop_requested,
                                ProgressState* final_state = nullptr);

}  // namespace orb::render
