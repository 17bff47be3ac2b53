// The --help formatter every tool shares (tools/common/help_formatter): any
// option a tool registers is listed with a readable placeholder and none of
// CLI11's parser details.
#include "orb/cli/help_formatter.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// The help line of `name` (the first line that shows it), or "".
std::string line_of(const std::string& help, const std::string& name) {
    size_t at = help.find(name);
    if (at == std::string::npos) return {};
    const size_t start = help.rfind('\n', at) + 1;
    return help.substr(start, help.find('\n', at) - start);
}

class HelpFormatterTest : public ::testing::Test {
protected:
    HelpFormatterTest() { app.formatter(std::make_shared<orb::cli::HelpFormatter>()); }

    CLI::App app{"A tool", "orb-example"};
    std::uint64_t spp = 0;
    int depth = 0;
    double exposure = 0;
    std::string mode, output, view, config, sample_range;
    std::optional<std::string> passes;
    bool flag = false, resume = true;
    std::vector<std::string> inputs;
    std::vector<float> centre;
};

TEST_F(HelpFormatterTest, ShowsEveryOptionWithAPlaceholderAndNoParserNoise) {
    app.add_option("inputs", inputs, "Input images");
    app.add_option("--spp", spp, "Samples per pixel")->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1000}));
    app.add_option("--max-depth", depth, "Path depth")->check(CLI::Range(0, 1024))->capture_default_str();
    app.add_option("--exposure", exposure, "Stops")->check(CLI::Range(-10.0, 10.0));
    app.add_option("--mode", mode, "Light transport")->check(CLI::IsMember({"global", "direct"}));
    app.add_option("-o,--output", output, "Where to write")->required();
    app.add_option("--view", view, "Display view")->default_str("sRGB");
    app.add_option("--config", config, "Colour config");
    app.add_option("--sample-range", sample_range, "A slice")->check(CLI::Validator("START:COUNT"));
    app.add_option("--passes", passes, "Layers");
    auto* half = app.add_flag("--half", flag, "Half floats");
    app.add_flag("--resume,!--no-resume", resume, "Continue")->excludes(half);
    app.add_option("--centre", centre, "A point")->expected(3);

    const std::string help = app.help();
    for (const char* noise : {"UINT", "TEXT", "FLOAT", "INT:", "{false}", "{true}", "in [", "Excludes:", "Needs:",
                              "REQUIRED", "=sRGB", "=0"})
        EXPECT_THAT(help, Not(HasSubstr(noise))) << help;

    EXPECT_THAT(line_of(help, "--spp"), HasSubstr("--spp N "));
    EXPECT_THAT(line_of(help, "--max-depth"), HasSubstr("--max-depth N "));
    EXPECT_THAT(line_of(help, "--exposure"), HasSubstr("--exposure X "));
    EXPECT_THAT(line_of(help, "--mode"), HasSubstr("--mode global|direct "));
    EXPECT_THAT(line_of(help, "--output"), HasSubstr("-o, --output FILE "));
    EXPECT_THAT(line_of(help, "--view"), HasSubstr("--view VIEW "));
    EXPECT_THAT(line_of(help, "--config"), HasSubstr("--config FILE "));
    EXPECT_THAT(line_of(help, "--sample-range"), HasSubstr("--sample-range START:COUNT "));
    EXPECT_THAT(line_of(help, "--passes"), HasSubstr("--passes PASSES "));
    EXPECT_THAT(line_of(help, "--half"), HasSubstr("--half "));
    EXPECT_THAT(line_of(help, "--resume"), HasSubstr("--resume, --no-resume "));
    EXPECT_THAT(line_of(help, "--centre"), HasSubstr("--centre X Y Z "));
    EXPECT_THAT(line_of(help, "  inputs"), HasSubstr("Input images"));
    EXPECT_THAT(help, HasSubstr("Usage: orb-example [OPTIONS] inputs..."));
    // Descriptions are kept whole.
    for (const char* description : {"Samples per pixel", "Path depth", "Stops", "Light transport", "Where to write",
                                    "Display view", "Colour config", "A slice", "Layers", "Half floats", "Continue",
                                    "A point"})
        EXPECT_THAT(help, HasSubstr(description));
}

TEST_F(HelpFormatterTest, KeepsAPlaceholderTheToolChose) {
    app.add_option("--frames", view, "Frames to render")->option_text("SPEC");
    EXPECT_THAT(line_of(app.help(), "--frames"), HasSubstr("--frames SPEC "));
}

TEST_F(HelpFormatterTest, AValidatorsPlaceholderWordIsKeptWithoutItsDetails) {
    double seconds = 0;
    app.add_option("--time", seconds, "Seconds")->check(CLI::Validator("SECONDS>0"));
    app.add_option("--scene", config, "A scene")->check(CLI::ExistingFile);
    app.add_option("--inputs", output, "A folder")->check(CLI::ExistingPath);
    app.add_option("--gain", exposure, "A gain")->check(CLI::PositiveNumber);
    const std::string help = app.help();
    EXPECT_THAT(line_of(help, "--time"), HasSubstr("--time SECONDS "));
    EXPECT_THAT(line_of(help, "--scene"), HasSubstr("--scene FILE "));
    EXPECT_THAT(line_of(help, "--inputs"), HasSubstr("--inputs PATH "));
    EXPECT_THAT(line_of(help, "--gain"), HasSubstr("--gain X "));
}

TEST_F(HelpFormatterTest, ALongChoiceListIsLeftToTheDescription) {
    app.add_option("--compression", mode, "EXR compression: none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab")
        ->check(CLI::IsMember({"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"}));
    const std::string line = line_of(app.help(), "--compression");
    EXPECT_THAT(line, HasSubstr("--compression COMPRESSION "));
    EXPECT_THAT(line, Not(HasSubstr("{")));
}

}  // namespace
