// The film follows its channel table (kernels/include/orb/kernels/film_channels.h):
// clear values, and how films of different samples combine.
#include <gtest/gtest.h>

#include <cmath>

#include "orb/film/film.h"

namespace orb {
namespace {

Film filled(float value, SampleRange range)
{
    Film film;
    film.resize(3, 2);
    for (const film::ChannelInfo& info : film::kChannels)
        for (float& v : film.channel(info.channel)) v = value;
    film.samples_per_pixel = range.count;
    film.sample_ranges = SampleRanges(range);
    return film;
}

TEST(FilmTable, ChannelsAreTheNamedMembersClearedAsTheTableSays)
{
    Film film;
    film.resize(4, 3);
    EXPECT_EQ(&film.channel(film::Channel::radiance), &film.radiance);
    EXPECT_EQ(&film.channel(film::Channel::object_id), &film.object_id);
    for (const film::ChannelInfo& info : film::kChannels) {
        const std::vector<float>& values = film.channel(info.channel);
        ASSERT_EQ(values.size(), 12u * static_cast<std::size_t>(info.components)) << info.name;
        for (float v : values) ASSERT_EQ(v, info.clear) << info.name;
    }
    EXPECT_TRUE(std::isinf(film.depth[0]));
    EXPECT_EQ(film.object_id[0], -1.0f);
    EXPECT_EQ(film.samples_per_pixel, 0u);
}

TEST(FilmTable, SumsAddAndCentreRayValuesComeFromTheLowestSamples)
{
    // Whichever order the slices arrive in, the Same channels are those of
    // the slice holding sample 0 (value 1 here), and the sums add.
    for (bool low_first : {true, false}) {
        const Film low = filled(1.0f, {0, 4});
        const Film high = filled(5.0f, {4, 2});
        Film sum;
        sum.resize(3, 2);
        sum.accumulate(low_first ? low : high);
        sum.accumulate(low_first ? high : low);
        EXPECT_EQ(sum.samples_per_pixel, 6u);
        EXPECT_EQ(sum.sample_ranges.format(), "0:6");
        for (const film::ChannelInfo& info : film::kChannels) {
            const float expected = info.merge == film::MergeRule::Sum ? 6.0f : 1.0f;
            for (float v : sum.channel(info.channel)) ASSERT_EQ(v, expected) << info.name << " low_first " << low_first;
        }
    }
}

// Films of a render that computed only some channels combine those alone
// (Renderer::read_film with several devices): the others are left as they
// are, and may even be missing from the film added.
TEST(FilmTable, OnlyTheChannelsAskedForCombine)
{
    const std::uint32_t beauty = film::channel_bit(film::Channel::radiance) | film::channel_bit(film::Channel::alpha);
    Film sum = filled(1.0f, {0, 4});
    Film other = filled(5.0f, {4, 2});
    other.albedo.clear();
    sum.accumulate(other, beauty);
    EXPECT_EQ(sum.samples_per_pixel, 6u);
    EXPECT_EQ(sum.sample_ranges.format(), "0:6");
    for (const film::ChannelInfo& info : film::kChannels) {
        const float expected = (beauty & film::channel_bit(info.channel)) != 0 ? 6.0f : 1.0f;
        for (float v : sum.channel(info.channel)) ASSERT_EQ(v, expected) << info.name;
    }
}

TEST(FilmTable, FilmsOfOverlappingSamplesOrAnotherSizeAreRefused)
{
    Film sum = filled(1.0f, {0, 4});
    EXPECT_THROW(sum.accumulate(filled(1.0f, {3, 2})), std::invalid_argument);
    Film small;
    small.resize(2, 2);
    EXPECT_THROW(sum.accumulate(small), std::invalid_argument);
    EXPECT_EQ(sum.samples_per_pixel, 4u);
}

TEST(FilmTable, AFilmThatSetsOnlyItsCountHoldsTheFirstSamples)
{
    Film film;
    film.resize(1, 1);
    film.samples_per_pixel = 5;
    EXPECT_EQ(film.held_ranges().format(), "0:5");
}

}  // namespace
}  // namespace orb
