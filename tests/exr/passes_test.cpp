#include <gtest/gtest.h>

#include <stdexcept>

#include "orb/exr/passes.h"

using namespace orb::exr;

TEST(Passes, ParsesAListInDocumentedOrderWithoutDuplicates) {
    EXPECT_EQ(parse_passes("albedo,beauty,albedo"), (std::vector<Pass>{Pass::Beauty, Pass::Albedo}));
    EXPECT_EQ(parse_passes("all"), image_passes());  // every layer but the sample counts
    EXPECT_EQ(parse_passes("all,samples"), all_passes());
    EXPECT_EQ(format_passes(parse_passes("id,depth")), "depth,id");
}

TEST(Passes, RejectsUnknownAndEmptyEntriesNamingThem) {
    try {
        parse_passes("beauty,shadow");
        FAIL() << "expected an error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("'shadow'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(parse_passes(""), std::invalid_argument);
    EXPECT_THROW(parse_passes("beauty,"), std::invalid_argument);
}

TEST(Passes, ChannelNamesAreTheDocumentedOnes) {
    EXPECT_EQ(pass_channels(Pass::Beauty), (std::vector<std::string>{"R", "G", "B", "A"}));
    EXPECT_EQ(pass_channels(Pass::Direct), (std::vector<std::string>{"direct.R", "direct.G", "direct.B"}));
    EXPECT_EQ(pass_channels(Pass::Normal), (std::vector<std::string>{"N.X", "N.Y", "N.Z"}));
    EXPECT_EQ(pass_channels(Pass::Depth), (std::vector<std::string>{"Z"}));
    EXPECT_EQ(pass_channels(Pass::Id), (std::vector<std::string>{"id"}));
    EXPECT_EQ(pass_resume_channels(Pass::Normal), (std::vector<std::string>{"orb.normalLength"}));
    EXPECT_TRUE(pass_resume_channels(Pass::Beauty).empty());
}
