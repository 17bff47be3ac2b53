// The denoiser's inputs gathered from a layer's three planes: every value in
// its interleaved place, and the first value that is not finite (channel by
// channel, then pixel by pixel, as the layers are checked elsewhere) named
// whichever block of the parallel copy it falls in.
#include <gtest/gtest.h>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "denoise_inputs.h"
#include "orb/scene/error.h"

namespace orb::denoise::detail {
namespace {

constexpr int kWidth = 500;
constexpr std::size_t kPixels = 500 * 400;  // several blocks of the parallel copy
const Names kNames{"R", "G", "B"};

std::vector<std::vector<float>> planes() {
    std::vector<std::vector<float>> p(3, std::vector<float>(kPixels));
    for (std::size_t c = 0; c < 3; ++c)
        for (std::size_t i = 0; i < kPixels; ++i) p[c][i] = static_cast<float>(i) * 0.5f + static_cast<float>(c);
    return p;
}

std::string gather_error(const std::vector<std::vector<float>>& p) {
    std::vector<float> out(3 * kPixels);
    try {
        interleave_into(out.data(), kPixels, kWidth, kNames, "beauty", "x.exr",
                        [&](int c, std::size_t i) { return p[static_cast<std::size_t>(c)][i]; });
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(DenoiseInputs, EveryValueGoesToItsInterleavedPlace) {
    const auto p = planes();
    std::vector<float> out(3 * kPixels, -1.0f);
    interleave_into(out.data(), kPixels, kWidth, kNames, "beauty", "x.exr",
                    [&](int c, std::size_t i) { return p[static_cast<std::size_t>(c)][i]; });
    for (std::size_t i = 0; i < kPixels; ++i)
        for (std::size_t c = 0; c < 3; ++c) ASSERT_EQ(out[3 * i + c], p[c][i]) << "pixel " << i << " channel " << c;
}

TEST(DenoiseInputs, NamesTheFirstValueThatIsNotFiniteChannelByChannel) {
    auto p = planes();
    p[2][10] = std::numeric_limits<float>::quiet_NaN();         // B, first block
    p[1][150123] = std::numeric_limits<float>::infinity();      // G, a later block: named first
    p[1][190000] = -std::numeric_limits<float>::infinity();     // G, later still
    EXPECT_NE(gather_error(p).find("x.exr: beauty pixel (123, 300) channel G is inf"), std::string::npos)
        << gather_error(p);
    p[1][150123] = 1;
    p[1][190000] = 1;
    EXPECT_NE(gather_error(p).find("x.exr: beauty pixel (10, 0) channel B is nan"), std::string::npos)
        << gather_error(p);
    p[2][10] = 1;
    p[0][kPixels - 1] = -std::numeric_limits<float>::quiet_NaN();  // the last value of the last block
    EXPECT_NE(gather_error(p).find("x.exr: beauty pixel (499, 399) channel R is"), std::string::npos)
        << gather_error(p);
    p[0][kPixels - 1] = std::numeric_limits<float>::max();  // large but finite: taken
    EXPECT_EQ(gather_error(p), "");
}

}  // namespace
}  // namespace orb::denoise::detail
