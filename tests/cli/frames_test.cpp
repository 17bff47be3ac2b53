// Frame lists (--frames) and output names with a frame number in them.
#include <gtest/gtest.h>

#include "orb/cli/frames.h"
#include "orb/cli/tool_main.h"

using orb::cli::expand_frame_pattern;
using orb::cli::has_frame_number;
using orb::cli::parse_frame_list;
using orb::cli::UsageError;

TEST(FrameList, RangesStepsAndListsInTheOrderGiven) {
    EXPECT_EQ(parse_frame_list("7", "--frames"), (std::vector<long>{7}));
    EXPECT_EQ(parse_frame_list("1-4", "--frames"), (std::vector<long>{1, 2, 3, 4}));
    EXPECT_EQ(parse_frame_list("1-10x3", "--frames"), (std::vector<long>{1, 4, 7, 10}));
    EXPECT_EQ(parse_frame_list("1,5,9-12", "--frames"), (std::vector<long>{1, 5, 9, 10, 11, 12}));
    EXPECT_EQ(parse_frame_list("9-10,1,10", "--frames"), (std::vector<long>{9, 10, 1}));  // duplicates once
    EXPECT_EQ(parse_frame_list("0-0", "--frames"), (std::vector<long>{0}));
}

TEST(FrameList, BadListsAreUsageErrorsNamingTheEntry) {
    for (const char* bad : {"", "a", "1-", "-3", "5-2", "1-10x0", "1-10x", "3x2", "1,,2", "1.5", "1-2-3",
                            "1234567890", "0-999999999"}) {
        try {
            parse_frame_list(bad, "--frames");
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const UsageError& e) {
            EXPECT_NE(std::string(e.what()).find("--frames"), std::string::npos) << e.what();
        }
    }
}

TEST(FramePattern, PrintfAndHashNumbers) {
    EXPECT_EQ(expand_frame_pattern("shots/beauty.%04d.exr", 12), "shots/beauty.0012.exr");
    EXPECT_EQ(expand_frame_pattern("shots/beauty.%d.exr", 12), "shots/beauty.12.exr");
    EXPECT_EQ(expand_frame_pattern("shots/beauty.####.exr", 12), "shots/beauty.0012.exr");
    EXPECT_EQ(expand_frame_pattern("b.#.exr", 12345), "b.12345.exr");  // wider numbers are not cut
    EXPECT_EQ(expand_frame_pattern("100%%_%03d.exr", 7), "100%_007.exr");
    EXPECT_TRUE(has_frame_number("a.####.exr"));
    EXPECT_TRUE(has_frame_number("a.%04d.exr"));
    EXPECT_FALSE(has_frame_number("a.exr"));
    EXPECT_FALSE(has_frame_number("a.%04d.%d.exr"));
    EXPECT_FALSE(has_frame_number("a.##.%d.exr"));
    EXPECT_FALSE(has_frame_number("a.%s.exr"));
    EXPECT_THROW(expand_frame_pattern("a.exr", 1), UsageError);
    EXPECT_THROW(expand_frame_pattern("a.%4d.exr", 1), UsageError);
    EXPECT_THROW(expand_frame_pattern("a.#.#.exr", 1), UsageError);
}
