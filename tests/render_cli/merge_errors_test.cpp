// orb-merge refuses anything that is not a slice of the same render, with
// one message naming the file, and leaves no output behind.
#include <OpenEXR/ImfRgbaFile.h>

#include <algorithm>
#include <filesystem>

#include "cli_fixture.h"

using namespace orb::test;

namespace {

class MergeCli : public RenderCli {
protected:
    void SetUp() override {
        RenderCli::SetUp();
        scene_ = write_scene(small_scene());
        ASSERT_EQ(render({scene_, "--sample-range", "0:2", "-o", path("a.exr"), "--seed", "4"}).exit_code, 0);
    }
    // A slice of samples 2:2, with extra orb-render arguments.
    std::string slice(const std::string& name, std::vector<std::string> extra = {}) {
        std::vector<std::string> args{scene_, "--sample-range", "2:2", "-o", path(name)};
        if (std::find(extra.begin(), extra.end(), "--seed") == extra.end()) args.insert(args.end(), {"--seed", "4"});
        args.insert(args.end(), extra.begin(), extra.end());
        const auto run = render(args);
        EXPECT_EQ(run.exit_code, 0) << run.err;
        return path(name);
    }
    void expect_refused(const std::vector<std::string>& inputs, const std::string& named, const std::string& says,
                        int exit_code = 1) {
        std::vector<std::string> args = inputs;
        args.insert(args.end(), {"-o", path("out.exr")});
        const auto run = merge(args);
        EXPECT_EQ(run.exit_code, exit_code) << run.err;
        EXPECT_NE(run.err.find(named), std::string::npos) << run.err;
        EXPECT_NE(run.err.find(says), std::string::npos) << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;  // one message
        EXPECT_FALSE(std::filesystem::exists(path("out.exr")));
    }
    std::string scene_;
};

}  // namespace

TEST_F(MergeCli, RefusesSlicesOfAnotherRender) {
    expect_refused({path("a.exr"), slice("seed.exr", {"--seed", "5"})}, "seed.exr", "orb:seed 5 differs");
    expect_refused({path("a.exr"), slice("depth.exr", {"--max-depth", "3"})}, "depth.exr", "orb:maxDepth 3");
    expect_refused({path("a.exr"), slice("mode.exr", {"--mode", "direct"})}, "mode.exr", "orb:mode direct");
    expect_refused({path("a.exr"), slice("size.exr", {"--width", "16"})}, "size.exr", "the width 16");
    expect_refused({path("a.exr"), slice("passes.exr", {"--passes", "beauty,albedo"})}, "passes.exr", "orb:passes beauty,albedo");
    expect_refused({path("a.exr"), slice("time.exr", {"--time-at", "1"})}, "time.exr", "orb:sceneTime 1");
    orb::Scene other = small_scene();
    other.spheres[1].radius = 0.6;
    const std::string changed = write_scene(other, "changed.json");
    ASSERT_EQ(render({changed, "--sample-range", "2:2", "-o", path("scene.exr"), "--seed", "4"}).exit_code, 0);
    expect_refused({path("a.exr"), path("scene.exr")}, "scene.exr", "orb:sceneHash");
}

TEST_F(MergeCli, RefusesOverlappingSamples) {
    ASSERT_EQ(render({scene_, "--sample-range", "1:3", "-o", path("b.exr"), "--seed", "4"}).exit_code, 0);
    expect_refused({path("b.exr"), path("a.exr")}, "b.exr", "its samples 1:3 overlap");
    expect_refused({path("a.exr"), path("a.exr")}, "a.exr", "overlap");
}

TEST_F(MergeCli, RefusesHalfForeignAndMissingFiles) {
    expect_refused({path("a.exr"), slice("half.exr", {"--half"})}, "half.exr", "--half");
    {
        std::vector<Imf::Rgba> pixels(32 * 24, Imf::Rgba(0.5f, 0.5f, 0.5f, 1.0f));
        Imf::RgbaOutputFile file(path("foreign.exr").c_str(), 32, 24, Imf::WRITE_RGBA);
        file.setFrameBuffer(pixels.data(), 1, 32);
        file.writePixels(24);
    }
    expect_refused({path("a.exr"), path("foreign.exr")}, "foreign.exr", "not an orb-render image");
    expect_refused({path("a.exr"), path("missing.exr")}, "missing.exr", "no such file");
}

TEST_F(MergeCli, UsageErrors) {
    const std::string b = slice("b.exr");
    const auto png = merge({path("a.exr"), b, "-o", path("out.png")});
    EXPECT_EQ(png.exit_code, 2);
    EXPECT_NE(png.err.find("orb-tonemap"), std::string::npos) << png.err;
    EXPECT_FALSE(std::filesystem::exists(path("out.png")));
    const auto no_output = merge({path("a.exr"), b});
    EXPECT_EQ(no_output.exit_code, 2);
    const auto no_input = merge({"-o", path("out.exr")});
    EXPECT_EQ(no_input.exit_code, 2);
    const auto stdin_input = merge({path("a.exr"), "-", "-o", path("out.exr")});
    EXPECT_EQ(stdin_input.exit_code, 2);
    // An output that is one of the inputs would destroy it.
    const auto over_input = merge({path("a.exr"), b, "-o", path("a.exr")});
    EXPECT_EQ(over_input.exit_code, 2);
    EXPECT_NE(over_input.err.find("refusing to overwrite an input"), std::string::npos) << over_input.err;
    EXPECT_TRUE(std::filesystem::exists(path("a.exr")));
}
