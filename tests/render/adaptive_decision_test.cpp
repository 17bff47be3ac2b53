// Adaptive sampling's decision on the device (kernels/adaptive.cl) against
// the host's reference (libfilm: pixel_relmse, frame_relmse,
// pixels_still_sampling) on the same film: the same frame estimate, bit for
// bit, and the same list of pixels that keep sampling, in the same order.
// The films are rendered ones and random sums that reach every branch of
// the estimate (no sample, one, a variance below zero by rounding, pixels
// on the threshold's edge), at sizes that leave a partial work-group.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>
#include <random>

#include "orb/film/pixel_error.h"
#include "orb/film/stopping_rule.h"
#include "orb/render/adaptive_sampler.h"
#include "orb/render/progressive.h"
#include "render_test_support.h"

namespace orb::render::test {
namespace {

RenderConfig decision_config(int width, int height, bool adaptive)
{
    RenderConfig config = small_config(width, height, 5);
    config.adaptive = adaptive;
    config.development.device_decisions = true;  // PoCL's too, which would decide on the host by default
    config.film_channels = film::channel_bit(film::Channel::radiance) |
                           film::channel_bit(film::Channel::radiance_sq) |
                           (adaptive ? film::channel_bit(film::Channel::sample_count) : 0u);
    return config;
}

Scene ball_under_sky()
{
    Scene scene;
    add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, MaterialType::Diffuse, {0.5, 0.5, 0.5}));
    add_sphere(scene, {1.2, 0.8, -1}, 0.3, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {4, 3, 2}));
    scene.environment.kind = EnvironmentKind::Color;
    scene.environment.color = {0.2, 0.3, 0.5};
    scene.camera.position = {0, 0, 5};
    scene.camera.target = {0, 0, 0};
    scene.camera.vfov_deg = 40.0;
    return scene;
}

struct HostDecision {
    double estimate = 0;
    std::vector<std::uint32_t> still_sampling;
};

HostDecision decide_on_host(const Renderer& renderer, std::optional<double> threshold,
                            const std::vector<std::uint32_t>& candidates)
{
    const Film film = renderer.read_film();
    const std::vector<double> errors = film::pixel_relmse(film);
    HostDecision decision;
    decision.estimate = film::frame_relmse(errors);
    if (threshold)
        decision.still_sampling = film::pixels_still_sampling(errors, film.width, film.height, *threshold, candidates);
    return decision;
}

std::vector<std::uint32_t> every_pixel(const Renderer& renderer)
{
    std::vector<std::uint32_t> all(static_cast<std::size_t>(renderer.pixel_count()));
    std::iota(all.begin(), all.end(), std::uint32_t{0});
    return all;
}

// Decides on the device and on the host among the renderer's active pixels
// (`candidates`, the host's copy) and expects the same; returns the list.
std::vector<std::uint32_t> expect_same_decision(Renderer& renderer, std::optional<double> threshold,
                                                const std::vector<std::uint32_t>& candidates, const char* what)
{
    const HostDecision host = decide_on_host(renderer, threshold, candidates);
    const std::optional<Renderer::Decision> device = renderer.decide_on_device(threshold);
    EXPECT_TRUE(device) << what;
    if (!device) return {};
    // The same bits: the same operations in the same order on both sides.
    EXPECT_EQ(device->estimated_relmse, host.estimate) << what;
    if (!threshold) return {};
    EXPECT_EQ(device->still_sampling, host.still_sampling.size()) << what;
    const std::vector<std::uint32_t> list = renderer.active_pixels();
    EXPECT_EQ(list, host.still_sampling) << what;
    EXPECT_EQ(renderer.active_pixel_count(), host.still_sampling.size()) << what;
    return list;
}

}  // namespace

TEST(DeviceDecision, PoclDecidesOnTheHostUnlessTheKnobSaysDevice)
{
    Renderer renderer(ball_under_sky(), decision_config(8, 8, true));
    EXPECT_TRUE(renderer.decides_on_device());  // PoCL has double precision
    RenderConfig config = decision_config(8, 8, true);
    config.development.device_decisions = false;
    Renderer on_host(ball_under_sky(), config);
    EXPECT_FALSE(on_host.decides_on_device());
    EXPECT_FALSE(on_host.decide_on_device(0.1));
    config.development.device_decisions.reset();
    Renderer by_default(ball_under_sky(), config);
    EXPECT_EQ(by_default.decides_on_device(), !by_default.device().is_cpu);
}

// A rendered film, decided on three times as a render would (the candidates
// of each decision the pixels kept by the one before), with a threshold that
// keeps some pixels and stops others each time.
TEST(DeviceDecision, DecidesAsTheHostOnARenderedFilmDecisionAfterDecision)
{
    const int width = 45, height = 23;  // 1035 pixels: four full work-groups and a partial one
    Renderer renderer(ball_under_sky(), decision_config(width, height, true));
    renderer.clear();
    const double threshold = 0.08;
    std::vector<std::uint32_t> candidates = every_pixel(renderer);
    for (int decision = 0; decision < 3; ++decision) {
        renderer.render_pass(16);
        const std::string what = "decision " + std::to_string(decision);
        const std::vector<std::uint32_t> kept = expect_same_decision(renderer, threshold, candidates, what.c_str());
        EXPECT_GT(kept.size(), 0u) << what;
        EXPECT_LT(kept.size(), candidates.size()) << what;
        candidates = kept;
    }
}

// Random sums: counts of 0 to 40 samples (0 and 1: an unknown error),
// squares from below the mean's square (a variance that rounds below zero)
// to far above it, means from 0 to bright; thresholds at which the pixels
// fall on both sides.
TEST(DeviceDecision, DecidesAsTheHostOnRandomSums)
{
    const int width = 301, height = 97;
    Renderer renderer(ball_under_sky(), decision_config(width, height, true));
    std::mt19937_64 random(42);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    Film film;
    film.resize(width, height, renderer.config().film_channels);
    film.samples_per_pixel = 40;
    for (std::size_t i = 0; i < film.pixel_count(); ++i) {
        // 1% of the pixels hold 0 or 1 sample, the others 2 to 40.
        const float n = unit(random) < 0.01f ? static_cast<float>(unit(random) < 0.5f)
                                             : 2.0f + static_cast<float>(static_cast<int>(unit(random) * 39.0f));
        film.sample_count[i] = static_cast<film::Sum>(n);
        // 3% noisy (a sample variance up to the mean's square), 2% with a
        // square below the mean's (no variance), the others quiet, some
        // of those near the lowest threshold (a relative error of 1% at
        // two samples is a spread of 1e-4).
        const float kind = unit(random);
        for (int c = 0; c < 3; ++c) {
            const float mean = unit(random) < 0.1f ? 0.0f : unit(random) * (unit(random) < 0.2f ? 50.0f : 1.0f);
            const float spread = kind < 0.03f   ? 1.0f + unit(random)
                                 : kind < 0.05f ? 0.999f
                                                : 1.0f + 2e-4f * unit(random) * unit(random);
            film.radiance[i * 3 + c] = film::sum_units(film::Units::Fixed, mean * n);
            film.radiance_sq[i * 3 + c] = film::sum_units(film::Units::Fixed, mean * mean * spread * n);
        }
    }
    for (double threshold : {0.01, 0.05, 0.2}) {
        renderer.load_film(film);
        const std::string what = "threshold " + std::to_string(threshold);
        const std::vector<std::uint32_t> kept = expect_same_decision(renderer, threshold, every_pixel(renderer), what.c_str());
        EXPECT_GT(kept.size(), 0u) << what;
        EXPECT_LT(kept.size(), film.pixel_count()) << what;
        // Again among those kept: the candidates come from the device's list now.
        expect_same_decision(renderer, threshold * 0.5, kept, (what + ", again").c_str());
    }
}

// --target-error without a noise threshold: the frame's estimate alone, from
// a film without per-pixel counts (every pixel holds the film's samples).
TEST(DeviceDecision, EstimatesTheFrameAsTheHostWithoutPerPixelCounts)
{
    Renderer renderer(ball_under_sky(), decision_config(37, 29, false));
    renderer.clear();
    renderer.render_pass(16);
    expect_same_decision(renderer, std::nullopt, {}, "16 samples");
    renderer.render_pass(16);
    expect_same_decision(renderer, std::nullopt, {}, "32 samples");
}

// A whole adaptive render decided on the device and one decided on the
// host: the same decisions, so the same pixels sample the same samples.
TEST(DeviceDecision, AnAdaptiveRenderIsTheSameWithDecisionsOnEitherSide)
{
    AdaptiveSettings settings;
    settings.noise_threshold = 0.03;
    settings.target_error = 1e-5;
    std::vector<Film> films;
    std::vector<double> estimates;
    for (bool host : {false, true}) {
        RenderConfig config = decision_config(40, 30, true);
        config.development.device_decisions = !host;
        Renderer renderer(ball_under_sky(), config);
        renderer.clear();
        AdaptiveSampler sampler(renderer, settings, std::nullopt);
        ProgressiveLimits limits;
        limits.target_spp = 200;
        limits.gate = &sampler;
        const std::atomic<bool> never{false};
        render_progressively(renderer, limits, {}, never);
        EXPECT_GT(sampler.decisions(), 3) << (host ? "host" : "device");
        films.push_back(renderer.read_film());
        estimates.push_back(sampler.estimated_relmse().value_or(-1));
    }
    // The passes between decisions follow the pass timer, so the sums may
    // be grouped differently: the same bits all the same.
    EXPECT_EQ(films[0].sample_count, films[1].sample_count);
    expect_same_films(films[0], films[1]);
    EXPECT_NEAR(estimates[0], estimates[1], 1e-4 * estimates[1]);
    film::Sum fewest = 200;
    for (film::Sum count : films[0].sample_count) fewest = std::min(fewest, count);
    EXPECT_LT(fewest, 200);  // some pixels did stop
}

}  // namespace orb::render::test
