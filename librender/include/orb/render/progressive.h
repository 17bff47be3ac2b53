// Progressive rendering: passes until a sample or time budget is reached,
// with periodic checkpoints and a clean stop on request (SIGINT/SIGTERM).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include "orb/render/pass_renderer.h"

namespace orb::render {

struct ProgressiveLimits {
    std::uint64_t target_spp = 64;   // total samples per pixel, counting resumed ones
    double max_seconds = 0;          // 0 = no time limit
    double checkpoint_seconds = 0;   // 0 = no checkpoints
};

struct ProgressState {
    int pass = 0;
    std::uint64_t spp = 0;
    std::uint64_t target_spp = 0;
    double elapsed_seconds = 0;
    double samples_per_second = 0;  // pixel samples per second over this run
};

struct ProgressiveCallbacks {
    std::function<void(const ProgressState&)> on_pass;        // after every pass
    std::function<void(const ProgressState&)> on_checkpoint;  // when a checkpoint is due
};

enum class StopReason { ReachedSpp, ReachedTime, Interrupted };

// Renders until a limit is reached or `stop_requested` becomes true (checked
// between passes, so the pass in flight always completes).
StopReason render_progressively(PassRenderer& renderer, const ProgressiveLimits& limits,
                                const ProgressiveCallbacks& callbacks, const std::atomic<bool>& stop_requested,
                                ProgressState* final_state = nullptr);

}  // namespace orb::render
