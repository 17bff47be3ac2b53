// The set of sample indices a film holds: joined, ordered, never overlapping.
#include <gtest/gtest.h>

#include <stdexcept>

#include "orb/film/sample_ranges.h"

namespace orb {
namespace {

TEST(SampleRanges, TouchingRangesJoinAndTheSetIsOrdered)
{
    SampleRanges set;
    set.add({16, 8});
    set.add({0, 8});
    EXPECT_EQ(set.format(), "0:8,16:8");
    set.add({8, 8});  // fills the gap: one range
    EXPECT_EQ(set.format(), "0:24");
    EXPECT_EQ(set.total(), 24u);
    EXPECT_EQ(set.first(), 0u);
    EXPECT_EQ(set.end(), 24u);
    set.add({40, 0});  // empty: nothing
    EXPECT_EQ(set.ranges().size(), 1u);
}

TEST(SampleRanges, OverlapsAreRefusedAndLeaveTheSetAlone)
{
    SampleRanges set(SampleRange{10, 10});
    EXPECT_THROW(set.add({19, 5}), std::invalid_argument);
    EXPECT_THROW(set.add({0, 11}), std::invalid_argument);
    EXPECT_THROW(set.add({12, 2}), std::invalid_argument);
    EXPECT_EQ(set.format(), "10:10");
    EXPECT_FALSE(set.overlaps(SampleRange{20, 5}));
    EXPECT_TRUE(set.overlaps(SampleRanges::parse("0:5,15:1")));
    SampleRanges other = SampleRanges::parse("0:5,19:2");
    EXPECT_THROW(set.add(other), std::invalid_argument);
    EXPECT_EQ(set.format(), "10:10");  // nothing of `other` went in
}

TEST(SampleRanges, ParsesItsOwnSpellingInAnyOrder)
{
    EXPECT_EQ(SampleRanges::parse("32:8,0:16").format(), "0:16,32:8");
    EXPECT_EQ(SampleRanges::parse("0:16,16:16").format(), "0:32");
    EXPECT_EQ(SampleRanges::parse("18446744073709551614:1").end(), 18446744073709551615u);
    for (const char* bad : {"", "5", "5:", ":5", "5:0", "-1:4", "1:2,", "a:b", "0:4,2:4", "18446744073709551615:1",
                            "18446744073709551616:1", "1:2:3"})
        EXPECT_THROW(SampleRanges::parse(bad), std::invalid_argument) << bad;
}

TEST(SampleRanges, AStartAndCountOfTheCommandLine)
{
    const SampleRange r = parse_sample_range("64:32");
    EXPECT_EQ(r.first, 64u);
    EXPECT_EQ(r.count, 32u);
    EXPECT_THROW(parse_sample_range("64"), std::invalid_argument);
    EXPECT_THROW(parse_sample_range("64:0"), std::invalid_argument);
    EXPECT_THROW(parse_sample_range(" 64:1"), std::invalid_argument);
}

}  // namespace
}  // namespace orb
