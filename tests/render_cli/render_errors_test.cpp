// Bad input and bad usage: one clear message, the documented exit code, and
// no output file.
#include <filesystem>
#include <fstream>

#include "cli_fixture.h"

using namespace orb::test;

namespace {

int error_lines(const std::string& err) {
    int lines = 0;
    for (std::size_t at = err.find("orb-render: error: "); at != std::string::npos;
         at = err.find("orb-render: error: ", at + 1))
        ++lines;
    return lines;
}

}  // namespace

TEST_F(RenderCli, MissingSceneFileFailsWithOneMessage) {
    const auto run = render({path("nope.json"), "-o", path("out.exr")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(error_lines(run.err), 1) << run.err;
    EXPECT_NE(run.err.find("nope.json"), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(path("out.exr")));
}

TEST_F(RenderCli, BadJsonNamesWhereItIsWrong) {
    std::ofstream(path("bad.json")) << "{\"format\": \"orb-scene\", \"version\": 1, \"spheres\": [ {\"radius\": -1} ]";
    const auto run = render({path("bad.json"), "-o", path("out.exr")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(error_lines(run.err), 1) << run.err;
    EXPECT_NE(run.err.find("bad.json"), std::string::npos) << run.err;
    EXPECT_EQ(files(), std::vector<std::string>{"bad.json"});
}

TEST_F(RenderCli, UnknownDeviceFailsNamingTheChoices) {
    const auto run = render({write_scene(small_scene()), "-o", path("out.exr"), "--device", "no-such-device-xyz"});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(error_lines(run.err), 1) << run.err;
    EXPECT_NE(run.err.find("no-such-device-xyz"), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(path("out.exr")));
}

TEST_F(RenderCli, MissingOutputFolderFailsBeforeRendering) {
    const auto run = render({write_scene(small_scene()), "-o", path("no/such/dir/out.exr")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_NE(run.err.find("does not exist"), std::string::npos) << run.err;
}

TEST_F(RenderCli, UsageErrorsExitTwo) {
    const std::string scene = write_scene(small_scene());
    const std::vector<std::vector<std::string>> usages{
        {scene},                                                   // no -o
        {"-o", path("out.exr")},                                   // no scene
        {scene, "-o", path("out.exr"), "--spp", "0"},
        {scene, "-o", path("out.exr"), "--spp", "many"},
        {scene, "-o", path("out.exr"), "--time", "-1"},
        {scene, "-o", path("out.exr"), "--mode", "local"},
        {scene, "-o", path("out.exr"), "--passes", "beauty,shadows"},
        {scene, "-o", path("out.exr"), "--no-such-option"},
        {scene, "-o", "-", "--checkpoint", "1"},
        {scene, "--benchmark", "-o", path("out.exr")},
        {scene, "-o", path("out.exr"), "--resume", "-"},
    };
    for (const auto& args : usages) {
        const auto run = render(args);
        std::string joined;
        for (const auto& a : args) joined += a + " ";
        EXPECT_EQ(run.exit_code, 2) << joined << "\n" << run.err;
        EXPECT_NE(run.err.find("orb-render: error: "), std::string::npos) << joined << "\n" << run.err;
    }
    EXPECT_FALSE(std::filesystem::exists(path("out.exr")));
}

TEST_F(RenderCli, HelpListsOptionsAndExamples) {
    const auto run = render({"--help"});
    EXPECT_EQ(run.exit_code, 0);
    for (const char* text : {"--spp", "--time", "--checkpoint", "--resume", "--passes", "--half", "--benchmark",
                             "--list-devices", "--time-at", "Examples:", "orb-import"})
        EXPECT_NE(run.out.find(text), std::string::npos) << text;
}
