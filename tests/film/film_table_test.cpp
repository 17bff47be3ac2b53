// The film follows its channel table (libtables/include/orb/tables/film_channels.h):
// clear values, integer sums, and how films of different samples combine.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "orb/film/film.h"

namespace orb {
namespace {

// Every Sum channel's sums at `sum` units, every CentreRay value at `value`.
Film filled(film::Sum sum, float value, SampleRange range)
{
    Film film;
    film.resize(3, 2);
    for (const film::ChannelInfo& info : film::kChannels) {
        if (info.accumulation == film::Accumulation::Sum)
            for (film::Sum& s : film.sums(info.channel)) s = sum;
        else
            for (float& v : film.values(info.channel)) v = value;
    }
    film.samples_per_pixel = range.count;
    film.sample_ranges = SampleRanges(range);
    return film;
}

TEST(FilmTable, ChannelsAreTheNamedMembersClearedAsTheTableSays)
{
    Film film;
    film.resize(4, 3);
    EXPECT_EQ(&film.sums(film::Channel::radiance), &film.radiance);
    EXPECT_EQ(&film.values(film::Channel::object_id), &film.object_id);
    for (const film::ChannelInfo& info : film::kChannels) {
        ASSERT_EQ(film.entries(info.channel), 12u * static_cast<std::size_t>(info.components)) << info.name;
        ASSERT_EQ(film.bytes(info.channel).size(), 12u * film::pixel_bytes(info)) << info.name;
        if (info.accumulation == film::Accumulation::Sum)
            for (film::Sum s : film.sums(info.channel)) ASSERT_EQ(s, 0) << info.name;
        else
            for (float v : film.values(info.channel)) ASSERT_EQ(v, info.clear) << info.name;
    }
    EXPECT_TRUE(std::isinf(film.depth[0]));
    EXPECT_EQ(film.object_id[0], -1.0f);
    EXPECT_EQ(film.samples_per_pixel, 0u);
}

TEST(FilmTable, ASumChannelHasNoFloatValuesAndACentreRayChannelNoSums)
{
    Film film;
    film.resize(1, 1);
    EXPECT_THROW(film.values(film::Channel::radiance), std::logic_error);
    EXPECT_THROW(film.sums(film::Channel::depth), std::logic_error);
}

TEST(FilmTable, SumsAddAndCentreRayValuesComeFromTheLowestSamples)
{
    // Whichever order the slices arrive in, the Same channels are those of
    // the slice holding sample 0 (value 1 here), and the sums add.
    for (bool low_first : {true, false}) {
        const Film low = filled(1, 1.0f, {0, 4});
        const Film high = filled(5, 5.0f, {4, 2});
        Film sum;
        sum.resize(3, 2);
        sum.accumulate(low_first ? low : high);
        sum.accumulate(low_first ? high : low);
        EXPECT_EQ(sum.samples_per_pixel, 6u);
        EXPECT_EQ(sum.sample_ranges.format(), "0:6");
        for (const film::ChannelInfo& info : film::kChannels) {
            if (info.merge == film::MergeRule::Sum)
                for (film::Sum s : sum.sums(info.channel)) ASSERT_EQ(s, 6) << info.name << " low_first " << low_first;
            else
                for (float v : sum.values(info.channel)) ASSERT_EQ(v, 1.0f) << info.name << " low_first " << low_first;
        }
    }
}

// The point of integer sums: films of slices of one render add up to the
// same bits in any grouping and order, which float sums do not (a float
// sum of a small value and a large one rounds, differently in each
// grouping).
TEST(FilmTable, FilmsOfSlicesAddToTheSameBitsInAnyGroupingAndOrder)
{
    std::mt19937_64 random(7);
    std::uniform_int_distribution<film::Sum> units(0, film::Sum{1} << 50);
    std::vector<Film> slices;
    for (std::uint64_t s = 0; s < 5; ++s) {
        Film slice = filled(0, 2.0f + static_cast<float>(s), {10 * s, 10});
        for (const film::ChannelInfo& info : film::kChannels)
            if (info.accumulation == film::Accumulation::Sum)
                for (film::Sum& v : slice.sums(info.channel)) v = units(random);
        slices.push_back(std::move(slice));
    }
    Film in_order;
    in_order.resize(3, 2);
    for (const Film& slice : slices) in_order.accumulate(slice);

    // ((4 + 2) + (0 + 3)) + 1
    Film first = slices[4], second = slices[0];
    first.accumulate(slices[2]);
    second.accumulate(slices[3]);
    first.accumulate(second);
    first.accumulate(slices[1]);
    EXPECT_EQ(first.sample_ranges, in_order.sample_ranges);
    for (const film::ChannelInfo& info : film::kChannels) {
        if (info.accumulation == film::Accumulation::Sum)
            EXPECT_EQ(first.sums(info.channel), in_order.sums(info.channel)) << info.name;
        else
            EXPECT_EQ(first.values(info.channel), in_order.values(info.channel)) << info.name;  // slice 0's
    }
    EXPECT_EQ(in_order.depth[0], 2.0f);
}

TEST(FilmTable, ASumThatPassesTheLargestIntegerStaysThereInEveryGrouping)
{
    const film::Sum big = film::kSumRangeEnd;  // a sample clamped at the range's end converts to this
    EXPECT_EQ(film::add_sums(big, big - 1), std::numeric_limits<film::Sum>::max());  // exactly the largest
    EXPECT_EQ(film::add_sums(big, big), std::numeric_limits<film::Sum>::max());      // one past it: stays there
    EXPECT_EQ(film::add_sums(film::add_sums(big, big), big), std::numeric_limits<film::Sum>::max());
    EXPECT_EQ(film::add_sums(big, film::add_sums(big, big)), std::numeric_limits<film::Sum>::max());
    EXPECT_EQ(film::add_sums(std::numeric_limits<film::Sum>::max(), 1), std::numeric_limits<film::Sum>::max());
    EXPECT_EQ(film::add_sums(std::numeric_limits<film::Sum>::min(), -big), std::numeric_limits<film::Sum>::min());
}

TEST(FilmTable, SumsThatReachTheRangeAreFoundChannelByChannel)
{
    Film film = filled(5, 0.0f, {0, 1});
    EXPECT_TRUE(film::sums_out_of_range(film).empty());
    film.radiance[3 * 4 + 1] = film::kSumRangeEnd;  // pixel 4: (1, 1)
    film.radiance[3 * 5 + 2] = std::numeric_limits<film::Sum>::max();
    film.sample_count[0] = film::kSumRangeEnd;  // a count, not a Fixed sum: never out of range
    const std::vector<film::OutOfRange> out = film::sums_out_of_range(film);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].channel, film::Channel::radiance);
    EXPECT_EQ(out[0].pixels, 2u);
    EXPECT_EQ(out[0].first_pixel, 4u);
    EXPECT_NE(film::describe(out[0], film.width).find("the radiance sums of 2 pixels (the first at (1, 1))"),
              std::string::npos)
        << film::describe(out[0], film.width);
}

TEST(FilmTable, AValueBecomesWholeUnitsRoundedAndClampedToTheRange)
{
    const double unit = film::unit_value(film::Units::Fixed);
    EXPECT_EQ(unit, std::ldexp(1.0, -24));
    EXPECT_EQ(film::unit_value(film::Units::Count), 1.0);
    EXPECT_EQ(film::sum_units(film::Units::Fixed, 1.0), film::Sum{1} << 24);
    EXPECT_EQ(film::sum_units(film::Units::Fixed, 2.6 * unit), 3);
    EXPECT_EQ(film::sum_units(film::Units::Fixed, -1.0), 0);
    EXPECT_EQ(film::sum_units(film::Units::Fixed, std::nan("")), 0);
    EXPECT_EQ(film::sum_units(film::Units::Fixed, 1e300), film::kSumRangeEnd);
    EXPECT_EQ(film::sum_units(film::Units::SignedFixed, -0.5), -(film::Sum{1} << 23));
    EXPECT_EQ(film::sum_units(film::Units::Count, 7.4), 7);
    EXPECT_EQ(film::sum_value(film::Units::Fixed, film::Sum{3} << 23), 1.5);
}

// Films of a render that computed only some channels combine those alone
// (Renderer::read_film with several devices): the others are left as they
// are, and may even be missing from the film added.
TEST(FilmTable, OnlyTheChannelsAskedForCombine)
{
    const std::uint32_t beauty = film::channel_bit(film::Channel::radiance) | film::channel_bit(film::Channel::alpha);
    Film sum = filled(1, 1.0f, {0, 4});
    Film other = filled(5, 5.0f, {4, 2});
    other.albedo.clear();
    sum.accumulate(other, beauty);
    EXPECT_EQ(sum.samples_per_pixel, 6u);
    EXPECT_EQ(sum.sample_ranges.format(), "0:6");
    for (const film::ChannelInfo& info : film::kChannels) {
        const bool combined = (beauty & film::channel_bit(info.channel)) != 0;
        if (info.accumulation == film::Accumulation::Sum)
            for (film::Sum s : sum.sums(info.channel)) ASSERT_EQ(s, combined ? 6 : 1) << info.name;
        else
            for (float v : sum.values(info.channel)) ASSERT_EQ(v, 1.0f) << info.name;
    }
}

TEST(FilmTable, FilmsOfOverlappingSamplesOrAnotherSizeAreRefused)
{
    Film sum = filled(1, 1.0f, {0, 4});
    EXPECT_THROW(sum.accumulate(filled(1, 1.0f, {3, 2})), std::invalid_argument);
    Film small;
    small.resize(2, 2);
    EXPECT_THROW(sum.accumulate(small), std::invalid_argument);
    EXPECT_EQ(sum.samples_per_pixel, 4u);
}

TEST(FilmTable, AFilmHoldsAtMostTheSamplesItsSignedSumsCanCount)
{
    Film sum = filled(1, 1.0f, {0, film::kMaxSamplesPerPixel});
    EXPECT_THROW(sum.accumulate(filled(1, 1.0f, {film::kMaxSamplesPerPixel, 1})), std::invalid_argument);
    EXPECT_EQ(sum.samples_per_pixel, film::kMaxSamplesPerPixel);
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
