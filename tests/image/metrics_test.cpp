#include <gtest/gtest.h>

#include <cmath>

#include "orb/image/flip.h"
#include "orb/image/metrics.h"
#include "test_support.h"

using namespace orb::image;

TEST(Metrics, HandComputedValues) {
    Image ref(2, 1, {"R", "G", "B"}), test(2, 1, {"R", "G", "B"});
    ref.pixels = {0.5f, 0.5f, 0.5f, 1.0f, 0.0f, 0.25f};
    test.pixels = {0.5f, 0.7f, 0.5f, 0.9f, 0.0f, 0.25f};
    const ErrorStats s = compute_error_stats(ref, test);
    // Differences: 0, 0.2, 0, 0.1, 0, 0 over six values.
    EXPECT_NEAR(s.mean_abs_error, 0.3 / 6, 1e-7);
    EXPECT_NEAR(s.rmse, std::sqrt((0.04 + 0.01) / 6), 1e-7);
    EXPECT_NEAR(s.psnr, 20 * std::log10(1 / std::sqrt(0.05 / 6)), 1e-5);
    EXPECT_NEAR(s.relmse, (0.04 / (0.25 + 0.01) + 0.01 / (1.0 + 0.01)) / 6, 1e-6);
    EXPECT_NEAR(s.max_abs_error, 0.2, 1e-6);
    EXPECT_EQ(s.max_x, 0);
    EXPECT_EQ(s.max_y, 0);
    EXPECT_EQ(s.max_channel, "G");
    EXPECT_DOUBLE_EQ(percent_pixels_over(ref, test, 0.15), 50.0);
    EXPECT_DOUBLE_EQ(percent_pixels_over(ref, test, 0.05), 100.0);
    EXPECT_DOUBLE_EQ(percent_pixels_over(ref, test, 0.25), 0.0);
}

TEST(Metrics, PsnrPeakIsTheLargerOfOneAndTheBrightestValue) {
    Image ref(2, 1, {"R"}), test(2, 1, {"R"});
    ref.pixels = {4.0f, 0.0f};
    test.pixels = {3.0f, 0.0f};
    // rmse = sqrt(1/2); the peak is 4, from the reference.
    EXPECT_NEAR(compute_error_stats(ref, test).psnr, 20 * std::log10(4.0 / std::sqrt(0.5)), 1e-9);
}

TEST(Metrics, IdenticalImagesHaveInfinitePsnr) {
    const Image a = test::make_scene(16, 8, 3.0f);
    const ErrorStats s = compute_error_stats(a, a);
    EXPECT_EQ(s.rmse, 0.0);
    EXPECT_TRUE(std::isinf(s.psnr));
    EXPECT_EQ(s.relmse, 0.0);
}

TEST(Metrics, MatchingInfinitiesAreNoErrorButNanIs) {
    Image a(1, 1, {"Z"}), b(1, 1, {"Z"});
    a.pixels = {INFINITY};
    b.pixels = {INFINITY};
    EXPECT_EQ(compute_error_stats(a, b).rmse, 0.0);
    b.pixels = {NAN};
    const ErrorStats s = compute_error_stats(a, b);
    EXPECT_TRUE(std::isinf(s.rmse));
    EXPECT_EQ(s.nonfinite, 1u);
}

TEST(Flip, IdenticalImagesScoreZero) {
    const Image a = test::make_scene(40, 30, 4.0f);
    EXPECT_EQ(flip_hdr(a, a, default_flip_ppd()).mean, 0.0);
    Image ldr = a;
    for (float& v : ldr.pixels) v = std::min(v, 1.0f);
    EXPECT_EQ(flip_ldr(ldr, ldr, default_flip_ppd()).mean, 0.0);
}

TEST(Flip, BlackVersusWhiteIsNearlyMaximal) {
    Image black(24, 24, {"R", "G", "B"}, 0.0f), white(24, 24, {"R", "G", "B"}, 1.0f);
    const FlipResult r = flip_ldr(black, white, default_flip_ppd());
    EXPECT_GT(r.mean, 0.9);
    EXPECT_LE(r.max, 1.0);
}

TEST(Flip, MoreNoiseMeansMoreError) {
    const Image ref = test::make_scene(48, 32, 4.0f);
    const double small = flip_hdr(ref, test::make_scene(48, 32, 4.0f, 0.02f), default_flip_ppd()).mean;
    const double large = flip_hdr(ref, test::make_scene(48, 32, 4.0f, 0.2f), default_flip_ppd()).mean;
    EXPECT_GT(small, 0.0);
    EXPECT_LT(small, large);
}
