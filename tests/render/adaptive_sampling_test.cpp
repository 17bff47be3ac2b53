// Adaptive sampling (docs/design/adaptive-sampling.md): the decision
// schedule, the stopping rule, and renders that use them: flat pixels stop
// early and edges keep sampling, the furnace's answer stays within the noise
// of the samples drawn, --target-error's estimate is honest against a
// converged render, and a render continued from its film decides as the
// uninterrupted one did.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>

#include "orb/film/pixel_error.h"
#include "orb/film/stopping_rule.h"
#include "orb/render/adaptive_sampler.h"
#include "render_test_support.h"

namespace orb::render::test {
namespace {

std::vector<std::uint32_t> every_pixel(int width, int height)
{
    std::vector<std::uint32_t> all(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    std::iota(all.begin(), all.end(), std::uint32_t{0});
    return all;
}

RenderConfig adaptive_config(int width, int height, std::uint64_t seed = 7, int max_depth = 6)
{
    RenderConfig config = small_config(width, height, seed, max_depth);
    config.adaptive = true;
    // Decided on the device, as on GPUs (PoCL would decide on the host; the
    // two decide the same, adaptive_decision_test.cpp).
    config.development.device_decisions = true;
    return config;
}

struct AdaptiveRun {
    Film film;
    StopReason reason = StopReason::ReachedSpp;
    std::optional<double> estimate;
};

AdaptiveRun render_adaptively(Renderer& renderer, const AdaptiveSettings& settings, std::uint64_t spp,
                              std::optional<double> film_threshold = std::nullopt)
{
    AdaptiveSampler sampler(renderer, settings, film_threshold);
    ProgressiveLimits limits;
    limits.target_spp = spp;
    limits.gate = &sampler;
    const std::atomic<bool> never{false};
    AdaptiveRun run;
    run.reason = render_progressively(renderer, limits, {}, never);
    run.film = renderer.read_film();
    run.estimate = sampler.estimated_relmse();
    return run;
}

// A grey diffuse ball under a uniform environment of radiance 1, filling the
// middle of the image: pixels that see only the environment have no
// variance at all, pixels on the ball's outline a large one (a sample hits
// the ball or not).
Scene ball_under_sky()
{
    Scene scene;
    add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, MaterialType::Diffuse, {0.5, 0.5, 0.5}));
    scene.environment.kind = EnvironmentKind::Color;
    scene.environment.color = {1, 1, 1};
    scene.camera.position = {0, 0, 5};
    scene.camera.target = {0, 0, 0};
    scene.camera.vfov_deg = 40.0;
    return scene;
}

}  // namespace

TEST(AdaptiveSchedule, DecidesAtFixedCountsGrowingByAnEighth)
{
    std::vector<std::uint64_t> decisions;
    for (std::uint64_t spp = 0; decisions.size() < 12; spp = next_decision(spp, 16)) {
        if (spp > 0) decisions.push_back(spp);
    }
    EXPECT_EQ(decisions, (std::vector<std::uint64_t>{16, 32, 48, 64, 80, 96, 112, 128, 144, 162, 182, 204}));
    EXPECT_EQ(next_decision(20, 16), 32u);
    EXPECT_TRUE(is_decision(162, 16));
    EXPECT_FALSE(is_decision(161, 16));
    EXPECT_FALSE(is_decision(0, 16));
}

TEST(StoppingRule, AQuietPixelStopsUnlessANeighbourIsNoisy)
{
    // 5x3: one noisy pixel at (3, 1); an unknown error (one sample) at (0, 2).
    const int width = 5, height = 3;
    std::vector<double> relmse(15, 1e-6);
    relmse[1 * width + 3] = 0.04;  // relative error 0.2
    relmse[2 * width + 0] = std::numeric_limits<double>::infinity();
    const std::vector<std::uint32_t> kept =
        film::pixels_still_sampling(relmse, width, height, 0.1, every_pixel(width, height));
    // The noisy pixel and its 3x3 neighbourhood; the unknown one and its neighbours.
    EXPECT_EQ(kept, (std::vector<std::uint32_t>{2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14}));
    // A pixel that stopped does not come back, even beside a noisy one.
    const std::vector<std::uint32_t> later = film::pixels_still_sampling(relmse, width, height, 0.1, {3, 4, 13});
    EXPECT_EQ(later, (std::vector<std::uint32_t>{3, 4, 13}));
    // At a threshold above the relative error 0.2 only the unknown pixel keeps sampling, with its neighbours.
    EXPECT_EQ(film::pixels_still_sampling(relmse, width, height, 0.3, every_pixel(width, height)),
              (std::vector<std::uint32_t>{5, 6, 10, 11}));
}

TEST(PixelError, IsTheVarianceOfTheMeanOverOrbDiffsDenominator)
{
    Film film;
    film.resize(1, 1);
    film.samples_per_pixel = 4;
    film.sample_count = {4};
    // Samples 1, 1, 3, 3 in every channel: mean 2, sample variance 4/3, variance of the mean 1/3.
    const film::Sum one = film::Sum{1} << ORB_FILM_FIXED_BITS;  // 1 in a Fixed sum's units
    film.radiance = {8 * one, 8 * one, 8 * one};
    film.radiance_sq = {20 * one, 20 * one, 20 * one};
    EXPECT_NEAR(film::pixel_relmse(film, 0), (1.0 / 3.0) / (4.0 - 1.0 / 3.0 + film::kRelMseEpsilon), 1e-12);
    film.sample_count = {1};
    EXPECT_TRUE(std::isinf(film::pixel_relmse(film, 0)));
}

TEST(AdaptiveRender, TheSkyStopsAtTheFirstDecisionAndTheOutlineKeepsSampling)
{
    const int width = 32, height = 32;
    Renderer renderer(ball_under_sky(), adaptive_config(width, height));
    renderer.clear();
    AdaptiveSettings settings;
    settings.noise_threshold = 0.01;
    const std::uint64_t spp = 96;
    const AdaptiveRun run = render_adaptively(renderer, settings, spp);
    const Film& film = run.film;
    ASSERT_EQ(film.samples_per_pixel, spp);

    // The outline: coverage strictly between 0 and 1. Its relative error at
    // 96 samples (about 0.17 / sqrt(n)) is far above 1%: it samples to the end.
    // The sky two pixels or more from any covered pixel: zero variance, so
    // it stops at the first decision, 16 samples.
    const auto coverage = [&](int x, int y) {
        const std::size_t i = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
        return static_cast<float>(film.alpha[i]) / static_cast<float>(film.sample_count[i]);
    };
    int outline = 0, open_sky = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const film::Sum count = film.sample_count[static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)];
            const float a = coverage(x, y);
            if (a > 0.05f && a < 0.95f) {
                ++outline;
                EXPECT_EQ(count, static_cast<film::Sum>(spp)) << "outline pixel " << x << "," << y << " coverage " << a;
            }
            bool near_ball = false;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const int nx = std::clamp(x + dx, 0, width - 1), ny = std::clamp(y + dy, 0, height - 1);
                    if (coverage(nx, ny) > 0) near_ball = true;
                }
            if (!near_ball) {
                ++open_sky;
                EXPECT_EQ(count, 16) << "sky pixel " << x << "," << y;
            }
        }
    EXPECT_GT(outline, 20);
    EXPECT_GT(open_sky, 200);
    // The samples drawn are the counts' sum, fewer than every pixel at 96.
    const double drawn = static_cast<double>(std::accumulate(film.sample_count.begin(), film.sample_count.end(), film::Sum{0}));
    EXPECT_EQ(renderer.pixel_samples(), static_cast<std::uint64_t>(drawn));
    EXPECT_LT(drawn, 0.75 * spp * width * height);
}

// A white ball in a white furnace looks exactly L. Stopping on a noisy
// estimate could bias it (a pixel whose samples so far came out low looks
// quieter, since its variance is lower too, and stops there); the mean over
// the ball's pixels, each over its own count, must stay within 5 standard
// errors of L, the standard error from each pixel's variance over its own count.
TEST(AdaptiveRender, TheFurnaceStaysWithinTheNoiseOfTheSamplesDrawn)
{
    const Vec3 radiance{1.0, 2.0, 0.5};
    Scene scene;
    const int ball = add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, MaterialType::Diffuse, {1, 1, 1}));
    add_sphere(scene, {0, 0, 0}, 5.0, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, radiance));
    scene.camera.position = {0, 0, 3.5};
    scene.camera.target = {0, 0, 0};
    scene.camera.vfov_deg = 40.0;
    Renderer renderer(scene, adaptive_config(32, 32, 5, 64));
    renderer.clear();
    AdaptiveSettings settings;
    settings.noise_threshold = 0.03;
    const AdaptiveRun run = render_adaptively(renderer, settings, 256);
    const std::vector<std::size_t> pixels = interior_pixels_of(run.film, ball);
    ASSERT_GT(pixels.size(), 200u);
    // The stopping rule did stop the ball's pixels at different counts.
    film::Sum fewest = 256, most = 0;
    for (std::size_t p : pixels) {
        fewest = std::min(fewest, run.film.sample_count[p]);
        most = std::max(most, run.film.sample_count[p]);
    }
    EXPECT_LT(fewest, most);
    EXPECT_LT(fewest, 256);
    for (int c = 0; c < 3; ++c) {
        const PixelStatistics stats = radiance_statistics(run.film, pixels, c);
        const double l = radiance[static_cast<std::size_t>(c)];
        // Each sample rounds to the film's units (2^-24) by at most half of one.
        EXPECT_NEAR(stats.mean, l, 5.0 * stats.standard_error + 0x1p-24) << "channel " << c;
    }
}

// --target-error: the render stops once the estimate is below E, and the
// estimate is honest: the relMSE against a converged render of the same
// scene (orb-diff's definition) is within 1.5x of it.
TEST(AdaptiveRender, TheTargetErrorsEstimateMatchesTheErrorAgainstAConvergedRender)
{
    const Scene scene = load_scene_file(std::string(ORB_SCENES_DIR) + "/cornell.scn");
    const int width = 24, height = 18;
    RenderConfig config = small_config(width, height, 3);
    const Film reference = render(scene, config, {4096, 4096});

    config.seed = 11;  // other samples than the reference's
    config.development.device_decisions = true;
    Renderer renderer(scene, config);
    renderer.clear();
    AdaptiveSettings settings;
    settings.target_error = 0.004;
    const AdaptiveRun run = render_adaptively(renderer, settings, 8192);
    ASSERT_EQ(run.reason, StopReason::ReachedError);
    ASSERT_TRUE(run.estimate);
    EXPECT_LT(*run.estimate, 0.004);
    EXPECT_LT(run.film.samples_per_pixel, 8192u);

    double sum = 0;
    const std::size_t pixels = run.film.pixel_count();
    for (std::size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c) {
            const double a = film::sum_value(film::Units::Fixed, reference.radiance[i * 3 + c]) /
                             static_cast<double>(reference.samples_per_pixel);
            const double b = film::sum_value(film::Units::Fixed, run.film.radiance[i * 3 + c]) /
                             static_cast<double>(run.film.samples_per_pixel);
            sum += (b - a) * (b - a) / (a * a + film::kRelMseEpsilon);
        }
    const double measured = sum / static_cast<double>(pixels * 3);
    EXPECT_LT(measured, 1.5 * *run.estimate) << "estimate " << *run.estimate << " at " << run.film.samples_per_pixel << " spp";
    EXPECT_GT(measured, *run.estimate / 1.5) << "estimate " << *run.estimate << " at " << run.film.samples_per_pixel << " spp";
}

// Continued from its film after 40 samples (between the decisions at 32
// and 48), a render samples the pixels the uninterrupted one did and ends
// with the same image up to float rounding.
TEST(AdaptiveRender, AContinuedRenderDecidesAsTheUninterruptedOne)
{
    const Scene scene = ball_under_sky();
    AdaptiveSettings settings;
    settings.noise_threshold = 0.02;
    Renderer whole(scene, adaptive_config(24, 24));
    whole.clear();
    const Film uninterrupted = render_adaptively(whole, settings, 80).film;

    Renderer first(scene, adaptive_config(24, 24));
    first.clear();
    const Film part = render_adaptively(first, settings, 40).film;
    Renderer second(scene, adaptive_config(24, 24));
    second.load_film(part);
    const Film continued = render_adaptively(second, settings, 80, settings.noise_threshold).film;

    EXPECT_EQ(continued.sample_count, uninterrupted.sample_count);
    expect_same_films(uninterrupted, continued);
}

}  // namespace orb::render::test

namespace orb::render::test {

// The list of active pixels feeds one pixel a work-item at width 1 (GPUs run
// this) and one a lane at 4 and 16: the same samples of the same pixels,
// so the same counts and, up to float rounding, the same film.
TEST(AdaptiveRender, EveryWidthRendersTheSamePixelsFromTheList)
{
    const Scene scene = ball_under_sky();
    AdaptiveSettings settings;
    settings.noise_threshold = 0.02;
    std::vector<Film> films;
    for (int lanes : {0, 4, 16}) {
        RenderConfig config = adaptive_config(20, 14);
        config.development.simd_lanes = lanes;
        Renderer renderer(scene, config);
        renderer.clear();
        films.push_back(render_adaptively(renderer, settings, 64).film);
    }
    for (std::size_t i = 1; i < films.size(); ++i) {
        EXPECT_EQ(films[i].sample_count, films[0].sample_count) << i;
        expect_same_films_up_to_rounding(films[0], films[i]);
    }
    film::Sum fewest = 64;
    for (film::Sum count : films[0].sample_count) fewest = std::min(fewest, count);
    EXPECT_LT(fewest, 64);  // some pixels did stop
}

}  // namespace orb::render::test
