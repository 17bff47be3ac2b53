// The film's bookkeeping on the Cornell box: the light split adds up to the
// beauty, and the image depends only on the seed and the sample indices.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "render_test_support.h"

namespace orb::render::test {
namespace {

Scene cornell() { return load_scene_file(std::string(ORB_SCENES_DIR) + "/cornell.scn"); }

RenderConfig cornell_config(std::uint64_t seed = 42) { return small_config(24, 18, seed); }

TEST(FilmConsistency, DirectPlusIndirectPlusEmissionIsBeauty)
{
    const Film film = render(cornell(), cornell_config(), {16});
    const std::vector<double> radiance = sum_values(film, film::Channel::radiance);
    const std::vector<double> direct = sum_values(film, film::Channel::direct);
    const std::vector<double> indirect = sum_values(film, film::Channel::indirect);
    const std::vector<double> emission = sum_values(film, film::Channel::emission);
    double total_direct = 0, total_indirect = 0, total_emission = 0;
    // Per sample: the parts' float sum rounds once (2^-24 of it), and each of
    // the four values rounds to the film's units (half a unit, 2^-25).
    const double unit = film::unit_value(film::Units::Fixed);
    for (std::size_t i = 0; i < radiance.size(); ++i) {
        const double parts = direct[i] + indirect[i] + emission[i];
        ASSERT_NEAR(parts, radiance[i], 16 * (std::ldexp(1.0, -23) * std::abs(parts) + 2 * unit)) << i;
        total_direct += direct[i];
        total_indirect += indirect[i];
        total_emission += emission[i];
    }
    // The Cornell box has all three kinds of light.
    EXPECT_GT(total_direct, 0.0);
    EXPECT_GT(total_indirect, 0.0);
    EXPECT_GT(total_emission, 0.0);
}

TEST(FilmConsistency, SameSeedGivesIdenticalPixels)
{
    const Film a = render(cornell(), cornell_config(), {4, 4});
    const Film b = render(cornell(), cornell_config(), {4, 4});
    EXPECT_EQ(a.radiance, b.radiance);
    EXPECT_EQ(a.radiance_sq, b.radiance_sq);
    EXPECT_EQ(a.albedo, b.albedo);
}

TEST(FilmConsistency, DifferentSeedsGiveDifferentPixels)
{
    const Film a = render(cornell(), cornell_config(1), {8});
    const Film b = render(cornell(), cornell_config(2), {8});
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.radiance.size(); ++i) differing += a.radiance[i] != b.radiance[i];
    EXPECT_GT(differing, a.radiance.size() / 2);
}

TEST(FilmConsistency, PassSplitsDoNotChangeTheImage)
{
    const Film one_pass = render(cornell(), cornell_config(), {8});
    const Film eight_passes = render(cornell(), cornell_config(), {1, 1, 1, 1, 1, 1, 1, 1});
    const Film uneven = render(cornell(), cornell_config(), {3, 5});
    expect_same_films(one_pass, eight_passes);
    expect_same_films(one_pass, uneven);
}

TEST(FilmConsistency, ResumingFromAFilmContinuesTheSameRender)
{
    const Film uninterrupted = render(cornell(), cornell_config(), {3, 5});
    Film checkpoint = render(cornell(), cornell_config(), {3});
    ASSERT_EQ(checkpoint.samples_per_pixel, 3u);

    Renderer resumed(cornell(), cornell_config());
    resumed.load_film(checkpoint);
    EXPECT_EQ(resumed.samples_per_pixel(), 3u);
    resumed.render_pass(5);
    const Film finished = resumed.read_film();
    EXPECT_EQ(finished.samples_per_pixel, 8u);
    // Same passes, same sums: bit-identical, not merely close.
    EXPECT_EQ(finished.radiance, uninterrupted.radiance);
    expect_same_films(finished, uninterrupted);
}

TEST(FilmConsistency, LoadFilmRejectsAnotherSize)
{
    Renderer renderer(cornell(), cornell_config());
    Film wrong;
    wrong.resize(10, 10);
    EXPECT_THROW(renderer.load_film(wrong), std::invalid_argument);
}

TEST(FilmConsistency, ChannelsHoldSensibleValues)
{
    const Film film = render(cornell(), cornell_config(), {4});
    const std::vector<double> normal = sum_values(film, film::Channel::normal);
    const std::vector<double> albedo = sum_values(film, film::Channel::albedo);
    const std::vector<double> radiance = sum_values(film, film::Channel::radiance);
    const std::vector<double> radiance_sq = sum_values(film, film::Channel::radiance_sq);
    for (std::size_t p = 0; p < film.pixel_count(); ++p) {
        EXPECT_EQ(film.alpha[p], 4);  // the box is closed: every camera ray hits
        EXPECT_TRUE(std::isfinite(film.depth[p]));
        EXPECT_GE(film.object_id[p], 0.0f);
        EXPECT_LT(film.object_id[p], 9.0f);
        // Normals face the camera ray, are unit length per sample.
        const double nx = normal[p * 3] / 4, ny = normal[p * 3 + 1] / 4, nz = normal[p * 3 + 2] / 4;
        EXPECT_LE(std::sqrt(nx * nx + ny * ny + nz * nz), 1.0 + 1e-5);
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(albedo[p * 3 + c], 0.0);
            EXPECT_LE(albedo[p * 3 + c], 4.0);
            EXPECT_GE(radiance_sq[p * 3 + c] * 4, radiance[p * 3 + c] * radiance[p * 3 + c] * 0.999);
        }
    }
}

TEST(FilmConsistency, HostFilmAccumulateAddsSumsAndCounts)
{
    const Film a = render(cornell(), cornell_config(), {2});
    Film b = a;  // the same sums, standing for the samples after a's
    b.sample_ranges = SampleRanges(SampleRange{2, 2});
    Film sum;
    sum.resize(a.width, a.height);
    sum.accumulate(a);
    sum.accumulate(b);
    EXPECT_EQ(sum.samples_per_pixel, 4u);
    EXPECT_EQ(sum.sample_ranges.format(), "0:4");
    EXPECT_THROW(sum.accumulate(a), std::invalid_argument);  // its samples are in already
    EXPECT_EQ(sum.radiance[5], a.radiance[5] * 2);
    EXPECT_EQ(sum.depth, a.depth);
    EXPECT_EQ(sum.object_id, a.object_id);
}

}  // namespace
}  // namespace orb::render::test
