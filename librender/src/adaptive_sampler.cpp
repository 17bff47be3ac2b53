#include "orb/render/adaptive_sampler.h"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <stdexcept>

#include "orb/film/pixel_error.h"
#include "orb/film/stopping_rule.h"

namespace orb::render {

std::uint64_t next_decision(std::uint64_t spp, std::uint64_t min_samples)
{
    const std::uint64_t step = std::max<std::uint64_t>(1, min_samples);
    std::uint64_t decision = step;
    while (decision <= spp) decision += std::max(step, decision / 8);
    return decision;
}

bool is_decision(std::uint64_t spp, std::uint64_t min_samples)
{
    return spp > 0 && next_decision(spp - 1, min_samples) == spp;
}

namespace {

void require_channels(const RenderConfig& config, const AdaptiveSettings& settings)
{
    using film::Channel;
    const std::uint32_t needed = film::channel_bit(Channel::radiance) | film::channel_bit(Channel::radiance_sq) |
                                 (settings.noise_threshold ? film::channel_bit(Channel::sample_count) : 0u);
    if ((config.film_channels & needed) != needed)
        throw std::invalid_argument("adaptive sampling needs the film's radiance, radiance_sq and sample_count channels");
    if (settings.noise_threshold && !config.adaptive)
        throw std::invalid_argument("a noise threshold needs a renderer made for adaptive sampling");
    if ((settings.noise_threshold && !(*settings.noise_threshold > 0)) ||
        (settings.target_error && !(*settings.target_error > 0)))
        throw std::invalid_argument("the noise threshold and the target error must be positive");
}

}  // namespace

AdaptiveSampler::AdaptiveSampler(Renderer& renderer, const AdaptiveSettings& settings,
                                 std::optional<double> film_threshold)
    : renderer_(renderer), settings_(settings), on_device_(renderer.decides_on_device())
{
    require_channels(renderer.config(), settings);
    const std::uint64_t spp = renderer.samples_per_pixel();
    const auto every_pixel = [&] {
        std::vector<std::uint32_t> all(static_cast<std::size_t>(renderer_.pixel_count()));
        std::iota(all.begin(), all.end(), std::uint32_t{0});
        return all;
    };
    // The renderer starts (after clear() or load_film()) with every pixel active.
    const auto every_pixel_active = [&] {
        if (!on_device_) active_ = every_pixel();  // the host's copy of the list, its decisions' candidates
    };
    if (spp == 0) {  // a fresh film: every pixel samples until the first decision
        if (settings_.noise_threshold) every_pixel_active();
        return;
    }
    const bool at_decision = is_decision(spp, settings_.min_samples);
    if (!settings_.noise_threshold) {
        if (at_decision) decide_among(nullptr);
        return;
    }
    renderer_.read_film(film_);
    if (film_threshold == settings_.noise_threshold && !film_.sample_count.empty()) {
        // The pixels that held every sample were still sampling.
        std::vector<std::uint32_t> candidates;
        for (std::size_t i = 0; i < film_.pixel_count(); ++i)
            if (static_cast<std::uint64_t>(film_.sample_count[i]) == spp) candidates.push_back(static_cast<std::uint32_t>(i));
        renderer_.set_active_pixels(candidates);
        if (!on_device_) active_ = std::move(candidates);
        if (at_decision) {
            decide_among(&active_);
        } else if (renderer_.active_pixel_count() == 0) {
            stop_ = StopReason::Converged;
        }
        return;
    }
    every_pixel_active();
    if (spp < settings_.min_samples) return;  // too few samples to decide on yet
    decide_among(&active_);
}

std::uint64_t AdaptiveSampler::next_decision(std::uint64_t spp) const
{
    return render::next_decision(spp, settings_.min_samples);
}

std::size_t AdaptiveSampler::active_pixel_count() const
{
    return settings_.noise_threshold ? renderer_.active_pixel_count() : static_cast<std::size_t>(renderer_.pixel_count());
}

void AdaptiveSampler::decide() { decide_among(&active_); }

void AdaptiveSampler::decide_among(const std::vector<std::uint32_t>* host_candidates)
{
    const auto began = std::chrono::steady_clock::now();
    if (on_device_) {
        // The candidates are the renderer's list, on the device.
        const std::optional<Renderer::Decision> decision = renderer_.decide_on_device(settings_.noise_threshold);
        if (!decision) throw std::logic_error("the renderer no longer decides on its device");
        estimated_relmse_ = decision->estimated_relmse;
        if (settings_.noise_threshold && decision->still_sampling == 0) stop_ = StopReason::Converged;
    } else {
        renderer_.read_film(film_);
        const std::vector<double> errors = film::pixel_relmse(film_);
        estimated_relmse_ = film::frame_relmse(errors);
        if (settings_.noise_threshold) {
            // Read in place: active_ is assigned only once the new list is made.
            static const std::vector<std::uint32_t> none;
            active_ = film::pixels_still_sampling(errors, film_.width, film_.height, *settings_.noise_threshold,
                                                  host_candidates ? *host_candidates : none);
            renderer_.set_active_pixels(active_);
            if (active_.empty()) stop_ = StopReason::Converged;
        }
    }
    if (settings_.target_error && *estimated_relmse_ < *settings_.target_error) stop_ = StopReason::ReachedError;
    ++decisions_;
    decision_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
}

}  // namespace orb::render
