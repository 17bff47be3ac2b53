#include "orb/render/progressive.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace orb::render {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

// Samples for the next pass: one for the very first pass, so a first image
// (checkpoint) exists as early as possible; then the device's suggestion,
// shrunk so a time budget is not overrun by much, never past the target.
std::uint64_t next_pass_samples(const PassRenderer& renderer, const ProgressiveLimits& limits, const ProgressState& state,
                                double seconds_per_sample_per_pixel) {
    const std::uint64_t remaining = limits.target_spp - state.spp;
    std::uint64_t samples =
        state.pass == 0 ? 1 : static_cast<std::uint64_t>(std::max(1, renderer.suggested_samples_per_pass()));
    if (limits.max_seconds > 0 && seconds_per_sample_per_pixel > 0) {
        const double time_left = limits.max_seconds - state.elapsed_seconds;
        const double affordable = std::floor(time_left / seconds_per_sample_per_pixel);
        samples = std::min<std::uint64_t>(samples, static_cast<std::uint64_t>(std::max(1.0, affordable)));
    }
    samples = std::min(samples, remaining);
    if (limits.gate) samples = std::min(samples, limits.gate->next_decision(state.spp) - state.spp);
    return samples;
}

}  // namespace

StopReason render_progressively(PassRenderer& renderer, const ProgressiveLimits& limits,
                                const ProgressiveCallbacks& callbacks, const std::atomic<bool>& stop_requested,
                                ProgressState* final_state) {
    const Clock::time_point start = Clock::now();
    const std::uint64_t start_pixel_samples = renderer.pixel_samples();

    ProgressState state;
    state.spp = renderer.samples_per_pixel();
    state.target_spp = limits.target_spp;

    Clock::time_point last_checkpoint = start;
    int last_checkpoint_pass = 0;
    bool checkpointed = false;
    const bool checkpoints = limits.checkpoint_seconds > 0 || limits.checkpoint_passes > 0;
    // The first checkpoint after the first pass, then one every so many passes or seconds.
    auto checkpoint_due = [&] {
        if (!checkpointed) return true;
        if (limits.checkpoint_passes > 0) return state.pass - last_checkpoint_pass >= limits.checkpoint_passes;
        return seconds_between(last_checkpoint, Clock::now()) >= limits.checkpoint_seconds;
    };
    double seconds_per_sample_per_pixel = 0;  // from the latest pass

    auto reached = [&](StopReason& reason) {
        if (stop_requested.load()) return reason = StopReason::Interrupted, true;
        if (limits.gate)
            if (const std::optional<StopReason> done = limits.gate->stop()) return reason = *done, true;
        if (state.spp >= limits.target_spp) return reason = StopReason::ReachedSpp, true;
        if (limits.max_seconds > 0 && state.elapsed_seconds >= limits.max_seconds)
            return reason = StopReason::ReachedTime, true;
        return false;
    };

    StopReason reason = StopReason::ReachedSpp;
    while (!reached(reason)) {
        const std::uint64_t samples = next_pass_samples(renderer, limits, state, seconds_per_sample_per_pixel);
        const std::uint64_t decision = limits.gate ? limits.gate->next_decision(state.spp) : 0;
        const Clock::time_point pass_start = Clock::now();
        renderer.render_pass(static_cast<int>(std::min<std::uint64_t>(samples, 1u << 30)));
        const Clock::time_point pass_end = Clock::now();

        seconds_per_sample_per_pixel = seconds_between(pass_start, pass_end) / static_cast<double>(samples);
        state.pass += 1;
        state.spp = renderer.samples_per_pixel();
        if (limits.gate && state.spp == decision) limits.gate->decide();
        state.elapsed_seconds = seconds_between(start, pass_end);
        state.samples_per_second =
            state.elapsed_seconds > 0
                ? static_cast<double>(renderer.pixel_samples() - start_pixel_samples) / state.elapsed_seconds
                : 0;
        if (callbacks.on_pass) callbacks.on_pass(state);

        // The final image is written by the caller once the loop ends, so a
        // checkpoint is only worth its time while more passes will follow.
        StopReason ignored;
        if (checkpoints && !reached(ignored) && checkpoint_due()) {
            if (callbacks.on_checkpoint) callbacks.on_checkpoint(state);
            checkpointed = true;
            last_checkpoint = Clock::now();
            last_checkpoint_pass = state.pass;
        }
    }

    state.elapsed_seconds = seconds_between(start, Clock::now());
    if (final_state) *final_state = state;
    return reason;
}

}  // namespace orb::render
