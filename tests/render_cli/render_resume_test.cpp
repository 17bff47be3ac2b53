// --resume: continuing a render gives the uninterrupted render's image (bit
// for bit from a file with exact sums: a render stopped short; within float
// rounding from a finished render's means), and a file that is not the same
// render is refused.
#include <OpenEXR/ImfRgbaFile.h>

#include <filesystem>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"

using namespace orb::test;
using orb::exr::testing::read_raw_exr;

TEST_F(RenderCli, ResumeEndsAtTheUninterruptedImage) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "-o", path("whole.exr"), "--spp", "9", "--seed", "5", "--passes", "all"}).exit_code, 0);
    // Stopped by --time after its first pass: it keeps its exact sums.
    ASSERT_EQ(render({scene, "-o", path("part.exr"), "--spp", "9", "--seed", "5", "--passes", "all", "--time", "0.000001"})
                  .exit_code,
              0);
    EXPECT_TRUE(has_exact_sums(read_raw_exr(path("part.exr"))));
    EXPECT_EQ(orb::exr::read_film_exr(path("part.exr")).film.samples_per_pixel, 1u);
    const auto resumed = render({scene, "--resume", path("part.exr"), "-o", path("resumed.exr")});
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_EQ(resumed.err.find("means only"), std::string::npos) << resumed.err;

    const auto film = orb::exr::read_film_exr(path("resumed.exr"));
    EXPECT_EQ(film.film.samples_per_pixel, 9u);
    EXPECT_EQ(film.metadata.seed, 5u);
    // Finished: the output holds no exact sums, as the uninterrupted one.
    EXPECT_FALSE(has_exact_sums(read_raw_exr(path("resumed.exr"))));
    expect_same_image(path("whole.exr"), path("resumed.exr"));
}

// A finished render keeps its means only (exact sums would double its size
// and its encoding time): continued to more samples, its sums are rebuilt
// from them, said in a warning, and the image is the uninterrupted one's
// within float rounding.
TEST_F(RenderCli, ResumeExtendsAFinishedRenderWithinFloatRounding) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "-o", path("whole.exr"), "--spp", "9", "--seed", "5"}).exit_code, 0);
    ASSERT_EQ(render({scene, "-o", path("part.exr"), "--spp", "4", "--seed", "5"}).exit_code, 0);
    EXPECT_FALSE(has_exact_sums(read_raw_exr(path("part.exr"))));
    const auto resumed = render({scene, "--resume", path("part.exr"), "-o", path("resumed.exr"), "--spp", "9"});
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_NE(resumed.err.find("warning: " + path("part.exr") + ": holds means only, no exact sums"), std::string::npos)
        << resumed.err;
    expect_same_within_float_rounding(read_raw_exr(path("whole.exr")), read_raw_exr(path("resumed.exr")));
}

TEST_F(RenderCli, ResumeInPlaceContinuesToTheStoredTarget) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "-o", path("whole.exr"), "--spp", "6", "--mode", "direct", "--max-depth", "2"}).exit_code, 0);
    // Two resumes in place (the output replacing its input), mode, depth and
    // target (orb:targetSpp) coming from the header each time; the render
    // stopped short by --time each time but the last.
    ASSERT_EQ(render({scene, "-o", path("out.exr"), "--spp", "6", "--mode", "direct", "--max-depth", "2", "--time",
                      "0.000001"})
                  .exit_code,
              0);
    ASSERT_EQ(render({scene, "--resume", path("out.exr"), "-o", path("out.exr"), "--time", "0.000001"}).exit_code, 0);
    const auto last = render({scene, "--resume", path("out.exr"), "-o", path("out.exr")});
    ASSERT_EQ(last.exit_code, 0) << last.err;
    const auto film = orb::exr::read_film_exr(path("out.exr"));
    EXPECT_EQ(film.film.samples_per_pixel, 6u);
    EXPECT_EQ(film.metadata.mode, "direct");  // from the header, not the defaults
    EXPECT_EQ(film.metadata.max_depth, 2);
    expect_same_image(read_raw_exr(path("whole.exr")), read_raw_exr(path("out.exr")));
    EXPECT_EQ(files(), (std::vector<std::string>{"out.exr", "scene.json", "whole.exr"}));
}

TEST_F(RenderCli, ResumeRefusesAnotherScene) {
    orb::Scene scene = small_scene();
    ASSERT_EQ(render({write_scene(scene), "-o", path("part.exr"), "--spp", "1"}).exit_code, 0);
    scene.spheres[1].radius = 0.6;
    const std::string changed = write_scene(scene, "changed.json");
    const auto run = render({changed, "--resume", path("part.exr"), "-o", path("out.exr"), "--spp", "2"});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_NE(run.err.find("different scene"), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(path("out.exr")));
}

TEST_F(RenderCli, ResumeRefusesAnotherSizeOrSeed) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "-o", path("part.exr"), "--spp", "1"}).exit_code, 0);
    const auto size = render({scene, "--resume", path("part.exr"), "-o", path("out.exr"), "--width", "16"});
    EXPECT_EQ(size.exit_code, 1);
    EXPECT_NE(size.err.find("--width 16 differs"), std::string::npos) << size.err;
    const auto seed = render({scene, "--resume", path("part.exr"), "-o", path("out.exr"), "--seed", "9"});
    EXPECT_EQ(seed.exit_code, 1);
    EXPECT_NE(seed.err.find("--seed 9 differs"), std::string::npos) << seed.err;
    EXPECT_FALSE(std::filesystem::exists(path("out.exr")));
}

TEST_F(RenderCli, ResumeRefusesAForeignExr) {
    {
        std::vector<Imf::Rgba> pixels(32 * 24, Imf::Rgba(0.5f, 0.5f, 0.5f, 1.0f));
        Imf::RgbaOutputFile file(path("foreign.exr").c_str(), 32, 24, Imf::WRITE_RGBA);
        file.setFrameBuffer(pixels.data(), 1, 32);
        file.writePixels(24);
    }
    const auto run =
        render({write_scene(small_scene()), "--resume", path("foreign.exr"), "-o", path("out.exr"), "--spp", "2"});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_NE(run.err.find("not an orb-render image"), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(path("out.exr")));
}

TEST_F(RenderCli, ResumeRefusesAHalfFile) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "-o", path("half.exr"), "--spp", "1", "--half"}).exit_code, 0);
    const auto run = render({scene, "--resume", path("half.exr"), "-o", path("out.exr"), "--spp", "2"});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_NE(run.err.find("--half"), std::string::npos) << run.err;
}

// The sampler is part of what a render is: a resume keeps it (from
// orb:sampler), refuses another one, and the two samplers give different
// images of the same samples.
TEST_F(RenderCli, ResumeKeepsTheSamplerAndRefusesAnother) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "-o", path("whole.exr"), "--spp", "5", "--sampler", "independent"}).exit_code, 0);
    ASSERT_EQ(
        render({scene, "-o", path("part.exr"), "--spp", "5", "--sampler", "independent", "--time", "0.000001"}).exit_code,
        0);
    const auto other = render({scene, "--resume", path("part.exr"), "-o", path("out.exr"), "--sampler", "sobol"});
    EXPECT_EQ(other.exit_code, 1);
    EXPECT_NE(other.err.find("--sampler sobol differs from the resumed render's orb:sampler independent"),
              std::string::npos)
        << other.err;
    EXPECT_FALSE(std::filesystem::exists(path("out.exr")));

    const auto resumed = render({scene, "--resume", path("part.exr"), "-o", path("out.exr"), "--spp", "5"});
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_EQ(orb::exr::read_film_exr(path("out.exr")).metadata.sampler, "independent");
    expect_same_image(read_raw_exr(path("whole.exr")), read_raw_exr(path("out.exr")));

    ASSERT_EQ(render({scene, "-o", path("sobol.exr"), "--spp", "5"}).exit_code, 0);
    EXPECT_EQ(orb::exr::read_film_exr(path("sobol.exr")).metadata.sampler, "sobol");
    EXPECT_NE(read_raw_exr(path("sobol.exr")).channels.at("R"), read_raw_exr(path("whole.exr")).channels.at("R"));
}

TEST_F(RenderCli, UnknownSamplerIsAUsageError) {
    const auto run = render({write_scene(small_scene()), "-o", path("out.exr"), "--sampler", "halton"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find("--sampler"), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(path("out.exr")));
}
