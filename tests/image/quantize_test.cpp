#include <gtest/gtest.h>

#include <cmath>

#include "orb/image/quantize.h"

using namespace orb::image;

TEST(Quantize, DitherStaysWithinOneCodeAndIsUnbiased) {
    // A flat field between two codes: dithering must mix the two neighbours in
    // proportion (so the mean is preserved) and never go further.
    const float value = (100.0f + 0.3f) / 255.0f;
    Image flat(64, 64, {"R", "G", "B"}, value);
    const auto codes = quantize_8bit_dithered(flat);
    double sum = 0;
    for (uint8_t c : codes) {
        ASSERT_TRUE(c == 100 || c == 101) << int(c);
        sum += c;
    }
    const double mean = sum / codes.size();
    // 12288 Bernoulli(0.3) draws: standard error sqrt(0.21/12288) = 0.0041; allow 5 sigma.
    EXPECT_NEAR(mean, 100.3, 5 * std::sqrt(0.21 / codes.size()));
}

TEST(Quantize, DitherIsDeterministicAndExactOnCodes) {
    Image ramp(256, 1, {"R"});
    for (int i = 0; i < 256; ++i) ramp.pixels[i] = i / 255.0f;
    const auto a = quantize_8bit_dithered(ramp), b = quantize_8bit_dithered(ramp);
    EXPECT_EQ(a, b);
    for (int i = 0; i < 256; ++i) EXPECT_EQ(a[i], i);  // exact code values stay exact
}

TEST(Quantize, ClampsOutOfRangeAndNan) {
    Image img(3, 1, {"R"});
    img.pixels = {-1.0f, 7.0f, NAN};
    const auto codes8 = quantize_8bit_dithered(img);
    EXPECT_EQ(codes8[0], 0);
    EXPECT_EQ(codes8[1], 255);
    EXPECT_EQ(codes8[2], 0);
    const auto codes16 = quantize_16bit(img);
    EXPECT_EQ(codes16[1], 65535);
}
