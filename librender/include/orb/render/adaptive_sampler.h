// Adaptive sampling (docs/design/adaptive-sampling.md): at fixed sample
// counts the film is read back and judged by its own error estimate
// (orb/film/pixel_error.h); pixels whose relative error is below the noise
// threshold stop (orb/film/stopping_rule.h), and later passes render only
// the others; the render ends when none is left, or when the frame's
// estimated relMSE is below the target error.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "orb/film/film.h"
#include "orb/render/progressive.h"
#include "orb/render/renderer.h"

namespace orb::render {

// No decision before this many samples: an estimate from fewer is too
// noisy to stop on (a pixel whose first few samples agree by chance).
inline constexpr std::uint64_t kAdaptiveMinSamples = 16;

struct AdaptiveSettings {
    // A pixel stops once sqrt(its estimated relMSE) is below this (> 0).
    std::optional<double> noise_threshold;
    // The render stops once the frame's estimated relMSE is below this (> 0).
    std::optional<double> target_error;
    std::uint64_t min_samples = kAdaptiveMinSamples;

    bool any() const { return noise_threshold.has_value() || target_error.has_value(); }
};

// The decisions' sample counts, a function of the film's samples per pixel
// alone (so a resumed render decides where an uninterrupted one does):
// min_samples, then each one min_samples or an eighth further, whichever is
// more: 16, 32, 48, ..., 128, 144, 162, 182, ... The first after `spp`.
std::uint64_t next_decision(std::uint64_t spp, std::uint64_t min_samples);
bool is_decision(std::uint64_t spp, std::uint64_t min_samples);

class AdaptiveSampler final : public PassGate {
public:
    // Starts on the renderer's film as it is: empty, or loaded to be
    // continued. `film_threshold` is the noise threshold a loaded film was
    // rendered with (none: without one). With the same threshold the pixels
    // that held every sample of the film go on, as they would have without
    // the interruption (at a decision's sample count they are decided on
    // again); with another, every pixel is decided on anew. Needs a
    // renderer with config().adaptive for a noise threshold, and the
    // radiance and radiance_sq channels (and sample_count for a threshold)
    // in config().film_channels (std::invalid_argument otherwise).
    AdaptiveSampler(Renderer& renderer, const AdaptiveSettings& settings, std::optional<double> film_threshold);

    std::uint64_t next_decision(std::uint64_t spp) const override;
    void decide() override;
    std::optional<StopReason> stop() const override { return stop_; }

    // The frame's estimated relMSE at the last decision (none before one).
    std::optional<double> estimated_relmse() const { return estimated_relmse_; }
    std::size_t active_pixel_count() const;
    // Decisions made, and the seconds they took (on the device: its
    // kernels and the totals' read-back; on the host: the film's read-back,
    // the estimates, the list's upload): what adaptive sampling costs on top
    // of the passes.
    int decisions() const { return decisions_; }
    double decision_seconds() const { return decision_seconds_; }

private:
    // Decides among the renderer's active pixels: on the device where the
    // renderer can (Renderer::decides_on_device), else on the host from the
    // film read back, among `host_candidates` (the same pixels, the host's copy).
    void decide_among(const std::vector<std::uint32_t>* host_candidates);

    Renderer& renderer_;
    AdaptiveSettings settings_;
    bool on_device_;  // the decisions run on the device, where the film and the list are
    Film film_;  // read back at each decision on the host, its memory reused
    // With a noise threshold and decisions on the host: the pixels still
    // sampling, as the renderer's list holds them.
    std::vector<std::uint32_t> active_;
    std::optional<StopReason> stop_;
    std::optional<double> estimated_relmse_;
    int decisions_ = 0;
    double decision_seconds_ = 0;
};

}  // namespace orb::render
