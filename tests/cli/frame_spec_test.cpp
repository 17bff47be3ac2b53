// The shared frame-list and frame-pattern grammar (tools/common, docs/frames.md).
#include "orb/cli/frame_spec.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "orb/cli/tool_main.h"

namespace {

using orb::cli::count_frame_fields;
using orb::cli::expand_frame_pattern;
using orb::cli::parse_frame_spec;
using orb::cli::UsageError;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

std::vector<int> frames(const char* text) { return parse_frame_spec(text).frames; }

// The message of the UsageError `text` raises ("" if it parses).
std::string spec_error(const std::string& text) {
    try {
        parse_frame_spec(text);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}

std::string pattern_error(const std::string& pattern) {
    try {
        expand_frame_pattern(pattern, 7);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}

TEST(FrameSpec, SingleFrame) { EXPECT_THAT(frames("12"), ElementsAre(12)); }

TEST(FrameSpec, RangeIncludesBothEnds) { EXPECT_THAT(frames("1-4"), ElementsAre(1, 2, 3, 4)); }

TEST(FrameSpec, RangeOfOneFrame) { EXPECT_THAT(frames("5-5"), ElementsAre(5)); }

TEST(FrameSpec, StepStartsAtFirstAndStopsAtOrBeforeLast) {
    EXPECT_THAT(frames("1-10x3"), ElementsAre(1, 4, 7, 10));
    EXPECT_THAT(frames("1-9x3"), ElementsAre(1, 4, 7));
    EXPECT_THAT(frames("0-2x5"), ElementsAre(0));
}

TEST(FrameSpec, ListOfItems) { EXPECT_THAT(frames("1,5,9-12"), ElementsAre(1, 5, 9, 10, 11, 12)); }

TEST(FrameSpec, KeepsWrittenOrderAndDropsRepeats) {
    // Every fourth frame first, then the rest: the preview-first order a user asks for.
    EXPECT_THAT(frames("1-9x4,1-5"), ElementsAre(1, 5, 9, 2, 3, 4));
    EXPECT_THAT(frames("3,3,3"), ElementsAre(3));
}

TEST(FrameSpec, SpacesAroundItemsAreIgnored) { EXPECT_THAT(frames(" 1 , 3-4 "), ElementsAre(1, 3, 4)); }

TEST(FrameSpec, FrameZeroAndTheLargestFrame) {
    EXPECT_THAT(frames("0"), ElementsAre(0));
    const std::string top = std::to_string(orb::cli::kMaxFrameNumber);
    EXPECT_THAT(parse_frame_spec(top + "-" + top).frames, ElementsAre(orb::cli::kMaxFrameNumber));
    EXPECT_THAT(spec_error(std::to_string(orb::cli::kMaxFrameNumber + 1)), HasSubstr("is larger than"));
}

TEST(FrameSpec, HugeStepDoesNotOverflow) {
    const std::string top = std::to_string(orb::cli::kMaxFrameNumber);
    EXPECT_THAT(parse_frame_spec("0-" + top + "x" + top).frames, ElementsAre(0, orb::cli::kMaxFrameNumber));
}

TEST(FrameSpec, TooManyFramesIsRefusedNotAllocated) {
    EXPECT_THAT(spec_error("0-99999999"), HasSubstr("more than 1000000 frames"));
    EXPECT_EQ(parse_frame_spec("1-1000000").size(), 1'000'000u);
}

TEST(FrameSpec, ErrorsQuoteTheTextAndSayWhatIsExpected) {
    const std::string e = spec_error("1-x");
    EXPECT_THAT(e, HasSubstr("frame list '1-x'"));
    EXPECT_THAT(e, HasSubstr("expected N, A-B, A-BxSTEP"));
}

TEST(FrameSpec, MalformedListsAreUsageErrors) {
    for (const char* bad : {"", " ", ",", "1,", ",1", "1,,2", "a", "1-", "-3", "1-2-3", "3-1", "1-5x0", "1-5x",
                            "5x2", "+1", "1.5", "0x10", "1 2", "1-5x-1", "-1-3", "99999999999999999999"}) {
        EXPECT_NE(spec_error(bad), "") << "'" << bad << "' was accepted";
    }
}

TEST(FrameSpec, ReversedRangeSaysSo) { EXPECT_THAT(spec_error("9-3"), HasSubstr("ends before it starts")); }

TEST(FramePattern, PrintfFields) {
    EXPECT_EQ(expand_frame_pattern("beauty.%04d.exr", 7), "beauty.0007.exr");
    EXPECT_EQ(expand_frame_pattern("beauty.%d.exr", 7), "beauty.7.exr");
    EXPECT_EQ(expand_frame_pattern("b.%09d.exr", 123), "b.000000123.exr");
}

TEST(FramePattern, BlenderHashRuns) {
    EXPECT_EQ(expand_frame_pattern("beauty.####.exr", 7), "beauty.0007.exr");
    EXPECT_EQ(expand_frame_pattern("beauty.#.exr", 7), "beauty.7.exr");
}

TEST(FramePattern, WiderNumbersAreWrittenInFull) {
    EXPECT_EQ(expand_frame_pattern("f.%02d", 12345), "f.12345");
    EXPECT_EQ(expand_frame_pattern("f.##", 12345), "f.12345");
}

TEST(FramePattern, EveryFieldGetsTheFrame) {
    EXPECT_EQ(expand_frame_pattern("shot/%04d/beauty.####.exr", 42), "shot/0042/beauty.0042.exr");
    EXPECT_EQ(count_frame_fields("shot/%04d/beauty.####.exr"), 2);
}

TEST(FramePattern, PercentPercentIsALiteralPercent) {
    EXPECT_EQ(expand_frame_pattern("100%%/f.%03d.exr", 5), "100%/f.005.exr");
    EXPECT_EQ(count_frame_fields("100%%.exr"), 0);
}

TEST(FramePattern, CountsFields) {
    EXPECT_EQ(count_frame_fields("plain.exr"), 0);
    EXPECT_EQ(count_frame_fields("f.%04d.exr"), 1);
    EXPECT_EQ(count_frame_fields("f.###.exr"), 1);
}

TEST(FramePattern, NoFieldIsAUsageErrorThatShowsHow) {
    EXPECT_THAT(pattern_error("beauty.exr"), HasSubstr("has no frame number"));
    EXPECT_THAT(pattern_error("beauty.exr"), HasSubstr("%04d"));
}

TEST(FramePattern, OtherConversionsAreRefused) {
    for (const char* bad : {"f.%s.exr", "f.%4d.exr", "f.%010d.exr", "f.%0d.exr", "f.%", "f.%0", "f.%04", "f.%x"}) {
        EXPECT_THAT(pattern_error(bad), HasSubstr("only % conversions")) << bad;
        EXPECT_THROW(count_frame_fields(bad), UsageError) << bad;
    }
}

TEST(FramePattern, NegativeFrameIsRefused) { EXPECT_THROW(expand_frame_pattern("f.%04d", -1), UsageError); }

}  // namespace
