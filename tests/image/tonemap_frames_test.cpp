// orb-tonemap on frame sequences: the shared frame-list grammar and --skip-existing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "test_support.h"

using namespace orb::image;
using namespace orb::image::test;
namespace fs = std::filesystem;

namespace {

const std::string kTonemap = quote(tonemap_exe());

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class TonemapFrames : public ::testing::Test {
protected:
    ScratchDir dir;
    // Frame f is a scene of peak brightness f, so each output tells which input made it.
    void write_frames(std::initializer_list<int> frames) {
        for (int f : frames) {
            char name[32];
            std::snprintf(name, sizeof name, "f.%04d.exr", f);
            write_exr(dir.path(name), make_scene(16, 8, static_cast<float>(f)));
        }
    }
};

}  // namespace

TEST_F(TonemapFrames, ListsStepsAndBlenderHashes) {
    write_frames({1, 3, 5, 9, 10});
    const auto r = run(kTonemap + " " + quote(dir.path("f.####.exr")) + " --frames 1-5x2,9-10 -o " +
                       quote(dir.path("o.%03d.png")) + " -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* made : {"o.001.png", "o.003.png", "o.005.png", "o.009.png", "o.010.png"})
        EXPECT_TRUE(fs::exists(dir.path(made))) << made;
    EXPECT_FALSE(fs::exists(dir.path("o.002.png")));
    // Each output comes from its own frame: tonemapping frame 3 alone gives the same bytes.
    ASSERT_EQ(run(kTonemap + " " + quote(dir.path("f.0003.exr")) + " -o " + quote(dir.path("one.png")) + " -q").exit_code, 0);
    EXPECT_EQ(read_bytes(dir.path("one.png")), read_bytes(dir.path("o.003.png")));
}

TEST_F(TonemapFrames, BadListsAndPatternsAreUsageErrors) {
    write_frames({1});
    struct Case {
        std::string input, frames, output, message;
    };
    const std::vector<Case> cases = {
        {"f.%04d.exr", "3-1", "o.%04d.png", "frame list '3-1': the range 3-1 ends before it starts"},
        {"f.%04d.exr", "1-", "o.%04d.png", "frame list '1-'"},
        {"f.%04d.exr", "1", "o.png", "--frames needs an output pattern"},
        {"f.0001.exr", "1", "o.%04d.png", "--frames needs one input pattern"},
        {"f.%s.exr", "1", "o.%04d.png", "the only % conversions"},
    };
    for (const Case& c : cases) {
        const auto r = run(kTonemap + " " + quote(dir.path(c.input)) + " --frames " + quote(c.frames) + " -o " +
                           quote(dir.path(c.output)));
        EXPECT_EQ(r.exit_code, 2) << c.frames << "\n" << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir.path("o.0001.png")));
    }
}

TEST_F(TonemapFrames, SkipExistingLeavesCurrentOutputsAlone) {
    write_frames({1, 2, 3});
    const std::string in = quote(dir.path("f.%04d.exr")), out = quote(dir.path("o.%04d.png"));
    // Frame 1's output is current; frame 2's input is gone but its output
    // exists (nothing to make it again from); frame 3's output is damaged.
    // (tonemap_skip_test.cpp has what makes an output stale.)
    for (const char* f : {"0001", "0002"})
        ASSERT_EQ(run(kTonemap + " " + quote(dir.path(std::string("f.") + f + ".exr")) + " -o " +
                      quote(dir.path(std::string("o.") + f + ".png")) + " -q")
                      .exit_code,
                  0);
    const std::string kept = read_bytes(dir.path("o.0001.png"));
    fs::remove(dir.path("f.0002.exr"));
    std::ofstream(dir.path("o.0003.png")) << "not a png";

    const auto r = run(kTonemap + " " + in + " --frames 1-3 --skip-existing -o " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_bytes(dir.path("o.0001.png")), kept);
    EXPECT_NE(r.err.find("o.0003.png"), std::string::npos) << "the damaged output is named: " << r.err;
    EXPECT_NE(r.err.find("skipped 2 of 3 outputs"), std::string::npos) << r.err;
    ASSERT_EQ(run(kTonemap + " " + quote(dir.path("f.0003.exr")) + " -o " + quote(dir.path("three.png")) + " -q").exit_code, 0);
    EXPECT_EQ(read_image(dir.path("o.0003.png")).pixels, read_image(dir.path("three.png")).pixels);

    // Without the flag every frame is made again, and the missing input is an error.
    write_frames({1});
    const auto again = run(kTonemap + " " + in + " --frames 1-3 -o " + out + " -q");
    EXPECT_EQ(again.exit_code, 1);
    EXPECT_NE(again.err.find("f.0002.exr"), std::string::npos) << again.err;
    EXPECT_NE(read_bytes(dir.path("o.0001.png")), kept) << "its record names the new frame 1";
}

TEST_F(TonemapFrames, SkipExistingWithOneImage) {
    write_frames({1});
    const std::string in = quote(dir.path("f.0001.exr")), out = dir.path("one.png");
    ASSERT_EQ(run(kTonemap + " " + in + " -o " + quote(out) + " -q").exit_code, 0);
    const std::string kept = read_bytes(out);
    const auto r = run(kTonemap + " " + in + " --skip-existing -o " + quote(out));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("skipped 1 of 1 output that is current"), std::string::npos) << r.err;
    EXPECT_EQ(read_bytes(out), kept);
}
