// orb-render as a part of a pipeline and a tool on its own: the Cornell box
// through orb-import, --list-devices and --benchmark.
#include <filesystem>
#include <regex>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"

using namespace orb::test;

namespace {

std::string quoted(const std::string& text) { return "'" + text + "'"; }

}  // namespace

TEST_F(RenderCli, CornellBoxRendersThroughOrbImportPipe) {
    const std::string cornell = std::string(ORB_SCENES_DIR) + "/cornell.scn";
    ASSERT_TRUE(std::filesystem::exists(cornell)) << cornell;
    // Without orb-import in this build, orb-render reads the .scn itself.
    const std::string import_exe = ORB_IMPORT_EXE;
    const std::string producer = import_exe.empty() ? "cat " + quoted(cornell) : quoted(import_exe) + " " + quoted(cornell);
    const std::string command = producer + " | " + quoted(render_exe()) +
                                " - -o - --width 32 --height 24 --spp 2 > " + quoted(path("cornell.exr"));
    const auto run = run_process({"/bin/sh", "-c", "set -e; " + command});
    ASSERT_EQ(run.exit_code, 0) << command << "\n" << run.err;
    const auto film = orb::exr::read_film_exr(path("cornell.exr"));
    EXPECT_EQ(film.film.width, 32);
    EXPECT_EQ(film.film.samples_per_pixel, 2u);
    double total = 0;
    for (float v : film.film.radiance) total += v;
    EXPECT_GT(total, 0.0) << "the Cornell box's light must light something";
}

TEST_F(RenderCli, ListDevicesShowsAtLeastTheCpu) {
    const auto run = render({"--list-devices"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("index"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("compute units"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("cpu"), std::string::npos) << run.out;
}

TEST_F(RenderCli, BenchmarkPrintsSamplesPerSecondAndWritesNoImage) {
    const auto run = render({write_scene(small_scene()), "--benchmark", "--benchmark-seconds", "0.5"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::smatch match;
    ASSERT_TRUE(std::regex_search(run.out, match, std::regex("samples_per_second=([0-9.eE+]+)\\n$"))) << run.out;
    EXPECT_GT(std::stod(match[1]), 0.0);
    EXPECT_EQ(files(), std::vector<std::string>{"scene.json"});
}
