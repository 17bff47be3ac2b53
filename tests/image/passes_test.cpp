#include <gtest/gtest.h>

#include "orb/image/passes.h"
#include "orb/image/visual_mapping.h"
#include "test_support.h"

using namespace orb::image;

TEST(Passes, FindsEveryOrbRenderPass) {
    const Image img = test::make_multipass(8, 4);
    const auto passes = available_passes(img);
    const std::vector<std::string> expected = {"beauty", "direct", "indirect", "emission", "albedo",
                                               "normal", "depth",  "variance", "id"};
    EXPECT_EQ(passes, expected);
}

// orb-render's bookkeeping channels (the normal's length, the exact sums of
// a file that may be continued) are not pictures: never listed as passes.
TEST(Passes, OrbsBookkeepingChannelsAreNoPasses) {
    const Image multipass = test::make_multipass(4, 2);
    std::vector<std::string> names = multipass.channel_names;
    for (const char* extra : {"orb.normalLength", "orb.sum.R.lo", "orb.sum.R.hi", "orb.sum.variance.G.lo"})
        names.push_back(extra);
    const Image img(4, 2, names);
    EXPECT_EQ(available_passes(img), available_passes(multipass));
}

TEST(Passes, ExtractsChannelsByName) {
    const Image img = test::make_multipass(8, 4);
    const Pass beauty = extract_pass(img, "beauty", "x.exr");
    EXPECT_TRUE(beauty.has_alpha);
    EXPECT_EQ(beauty.image.channel_names, (std::vector<std::string>{"R", "G", "B", "A"}));
    EXPECT_FLOAT_EQ(beauty.image.at(3, 2, 1), img.at(3, 2, img.find_channel("G")));

    const Pass direct = extract_pass(img, "direct", "x.exr");
    EXPECT_EQ(direct.kind, PassKind::Color);
    EXPECT_FLOAT_EQ(direct.image.at(5, 1, 2), img.at(5, 1, img.find_channel("direct.B")));

    const Pass normal = extract_pass(img, "N", "x.exr");  // synonym
    EXPECT_EQ(normal.name, "normal");
    EXPECT_EQ(normal.kind, PassKind::Normal);
    EXPECT_FLOAT_EQ(normal.image.at(0, 0, 2), img.at(0, 0, img.find_channel("N.Z")));

    const Pass depth = extract_pass(img, "depth", "x.exr");
    EXPECT_EQ(depth.image.channels(), 1);
    EXPECT_FLOAT_EQ(depth.image.at(4, 0, 0), 1.2f);
    EXPECT_EQ(extract_pass(img, "id", "x.exr").kind, PassKind::Id);
    EXPECT_EQ(extract_pass(img, "variance", "x.exr").kind, PassKind::Variance);
}

TEST(Passes, MissingPassNamesFileAndAlternatives) {
    const Image rgb = test::make_scene(4, 4, 1.0f);
    try {
        extract_pass(rgb, "direct", "plain.exr");
        FAIL() << "expected PassMissing";
    } catch (const PassMissing& e) {
        EXPECT_NE(std::string(e.what()).find("plain.exr"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("beauty"), std::string::npos);
    }
}

TEST(Passes, GreyscaleBecomesBeauty) {
    Image grey(2, 1, {"Y"});
    grey.pixels = {0.25f, 0.5f};
    const Pass p = extract_pass(grey, "beauty", "g.png");
    ASSERT_EQ(p.image.channels(), 3);
    EXPECT_FLOAT_EQ(p.image.at(1, 0, 0), 0.5f);
    EXPECT_FLOAT_EQ(p.image.at(1, 0, 2), 0.5f);
}

TEST(VisualMapping, NormalsDepthAndIds) {
    const Image img = test::make_multipass(32, 4);
    const Image n = visualize_data_pass(extract_pass(img, "normal", "x"));
    EXPECT_NEAR(n.at(0, 0, 0), 0.5f + 0.5f * img.at(0, 0, img.find_channel("N.X")), 1e-6f);
    const Image d = visualize_data_pass(extract_pass(img, "depth", "x"));
    EXPECT_FLOAT_EQ(d.at(0, 0, 0), 1.0f);    // nearest is white
    EXPECT_NEAR(d.at(31, 0, 0), 0.1f, 1e-5f);  // farthest is dim but visible
    const Image ids = visualize_data_pass(extract_pass(img, "id", "x"));
    // Pixels with the same id share a colour; different ids differ.
    EXPECT_EQ(ids.at(0, 0, 0), ids.at(15, 3, 0));
    EXPECT_NE(std::make_tuple(ids.at(0, 0, 0), ids.at(0, 0, 1), ids.at(0, 0, 2)),
              std::make_tuple(ids.at(16, 0, 0), ids.at(16, 0, 1), ids.at(16, 0, 2)));
}
