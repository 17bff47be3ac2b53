// Several devices in one process (--device all, --device 0,1): each pass's
// samples are split over the devices and their films summed, which gives the
// single-device render of the same samples bit for bit (the film's sums are
// integers). PoCL offers two device instances with POCL_DEVICES="pthread pthread".
#include <nlohmann/json.hpp>

#include <cmath>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"

using namespace orb::test;
using orb::exr::read_film_exr;

namespace {

// orb-render with two PoCL devices.
ProcessResult render_on_two(const std::vector<std::string>& args) {
    std::vector<std::string> argv{"/usr/bin/env", "POCL_DEVICES=pthread pthread", render_exe()};
    argv.insert(argv.end(), args.begin(), args.end());
    return run_process(argv);
}

// Two images of the same samples, added in different groupings (per
// device, then across devices): the same bits.
void expect_same_samples(const std::string& a, const std::string& b) {
    ASSERT_EQ(read_film_exr(a).film.sample_ranges, read_film_exr(b).film.sample_ranges);
    expect_same_image(a, b);
}

}  // namespace

TEST_F(RenderCli, TwoDevicesRenderTheImageOfOne) {
    const std::string scene = write_scene(small_scene());
    const auto two = render_on_two({scene, "--device", "all", "--spp", "24", "--seed", "3", "-o",
                                           path("two.exr"), "--stats-json", path("two.json")});
    ASSERT_EQ(two.exit_code, 0) << two.err;
    EXPECT_NE(two.err.find("devices: "), std::string::npos) << two.err;
    const auto one = render_on_two({scene, "--device", "1", "--spp", "24", "--seed", "3", "-o", path("one.exr")});
    ASSERT_EQ(one.exit_code, 0) << one.err;
    expect_same_samples(path("one.exr"), path("two.exr"));

    // Both devices took part, and their shares add up to the image.
    const auto stats = nlohmann::json::parse(read_text(path("two.json")));
    ASSERT_EQ(stats.at("devices").size(), 2u);
    const auto first = stats.at("devices")[0].at("spp").get<std::uint64_t>();
    const auto second = stats.at("devices")[1].at("spp").get<std::uint64_t>();
    EXPECT_GT(first, 0u);
    EXPECT_GT(second, 0u);
    EXPECT_EQ(first + second, 24u);
    EXPECT_NE(read_film_exr(path("two.exr")).metadata.device.find("; "), std::string::npos);
}

// With only the beauty computed, each device's film holds the other
// channels at their clear values, and the sum of the two films is still the
// one device's image.
TEST_F(RenderCli, TwoDevicesRenderTheBeautyOfOne) {
    const std::string scene = write_scene(small_scene());
    const std::vector<std::string> common{scene, "--spp", "12", "--seed", "5", "--passes", "beauty"};
    auto args = common;
    args.insert(args.end(), {"--device", "all", "-o", path("two.exr"), "--stats-json", path("two.json")});
    const auto two = render_on_two(args);
    ASSERT_EQ(two.exit_code, 0) << two.err;
    const auto stats = nlohmann::json::parse(read_text(path("two.json")));
    EXPECT_GT(stats.at("devices")[0].at("spp").get<std::uint64_t>(), 0u);
    EXPECT_GT(stats.at("devices")[1].at("spp").get<std::uint64_t>(), 0u);
    args = common;
    args.insert(args.end(), {"--device", "1", "-o", path("one.exr")});
    ASSERT_EQ(render_on_two(args).exit_code, 0);
    expect_same_samples(path("one.exr"), path("two.exr"));
}

TEST_F(RenderCli, TwoDevicesRenderASliceOfAFrame) {
    const std::string scene = write_scene(moving_ball_scene());
    const std::vector<std::string> common{scene, "--frame", "6", "--sample-range", "8:16"};
    auto args = common;
    args.insert(args.end(), {"--device", "0,1", "-o", path("two.exr")});
    const auto two = render_on_two(args);
    ASSERT_EQ(two.exit_code, 0) << two.err;
    args = common;
    args.insert(args.end(), {"--device", "0", "-o", path("one.exr")});
    ASSERT_EQ(render_on_two(args).exit_code, 0);
    expect_same_samples(path("one.exr"), path("two.exr"));
}

TEST_F(RenderCli, ADeviceListNamesEachDeviceOnce) {
    const std::string scene = write_scene(small_scene());
    const auto twice = render_on_two({scene, "--device", "0,0", "-o", path("out.exr")});
    EXPECT_EQ(twice.exit_code, 1);
    EXPECT_NE(twice.err.find("named twice"), std::string::npos) << twice.err;
    const auto missing = render_on_two({scene, "--device", "0,7", "-o", path("out.exr")});
    EXPECT_EQ(missing.exit_code, 1);
    EXPECT_NE(missing.err.find("no OpenCL device with index 7"), std::string::npos) << missing.err;
    const auto empty = render_on_two({scene, "--device", "0,", "-o", path("out.exr")});
    EXPECT_EQ(empty.exit_code, 1);
    EXPECT_EQ(files(), (std::vector<std::string>{"scene.json"}));
}
