// The --help formatter every tool shares (tools/common/help_formatter): any
// option a tool registers is listed with a readable placeholder and none of
// CLI11's parser details.
#include "orb/cli/help_formatter.h"
#include "orb/cli/help_wrapping.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <sstream>
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
    HelpFormatterTest() { app.formatter(std::make_shared<orb::cli::HelpFormatter>(80)); }

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

// Every line of `text`.
std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

TEST(HelpWrapping, BreaksAtSpacesWithinTheWidth) {
    EXPECT_EQ(orb::cli::wrap_words("one two  three four", 9), (std::vector<std::string>{"one two", "three", "four"}));
    // A word longer than the width stands alone rather than being cut.
    EXPECT_EQ(orb::cli::wrap_words("a unbreakable b", 5), (std::vector<std::string>{"a", "unbreakable", "b"}));
    EXPECT_TRUE(orb::cli::wrap_words("   ", 10).empty());
}

TEST(HelpWrapping, ProseContinuesUnindentedAndShortLinesStayAsTheyAre) {
    EXPECT_EQ(orb::cli::wrap_help_line("Exit status: 0 success,  1 failure", 80), "Exit status: 0 success,  1 failure");
    EXPECT_EQ(orb::cli::wrap_help_line("Exit status: 0 success, 1 failure", 20), "Exit status: 0\nsuccess, 1 failure");
}

TEST(HelpWrapping, AnExamplesCommentGoesUnderItsCommand) {
    EXPECT_EQ(orb::cli::wrap_help_line("  orb-import cloud.ply -o cloud.orb   PLY point cloud -> spheres", 40),
              "  orb-import cloud.ply -o cloud.orb\n      PLY point cloud -> spheres");
}

TEST(HelpWrapping, ALongCommandIsContinuedAsAShellReadsIt) {
    const std::string wrapped =
        orb::cli::wrap_help_line("  orb-render scene.json -o out.exr --spp 4096 --noise-threshold 0.02", 30);
    EXPECT_EQ(wrapped, "  orb-render scene.json -o \\\n      out.exr --spp 4096 \\\n      --noise-threshold 0.02");
    for (const std::string& line : lines_of(wrapped)) EXPECT_LE(line.size(), 30u) << line;
}

TEST_F(HelpFormatterTest, WrapsEveryLineToItsWidthWithDescriptionsPastTheNames) {
    std::string long_text;
    for (int i = 0; i < 30; ++i) long_text += "word" + std::to_string(i) + " ";
    app.description("A tool whose description is long: " + long_text);
    app.add_option("--spp", spp, "Samples per pixel: " + long_text);
    app.add_option("--a-very-long-option-name-indeed", view, "Which: " + long_text)->option_text("SOMETHING");
    app.add_flag("--half", flag, "Half floats");
    app.footer("Examples:\n  orb-example --spp 4 --a-very-long-option-name-indeed x --half   " + long_text +
               "\nExit status: " + long_text);
    const std::string help = app.help();
    std::size_t continued = 0;
    for (const std::string& line : lines_of(help)) {
        EXPECT_LE(line.size(), 80u) << line;
        continued += line.rfind(std::string(34, ' '), 0) == 0;
    }
    EXPECT_GT(continued, 2u) << help;  // the descriptions go on in their column
    EXPECT_THAT(help, HasSubstr("\n  --half                          Half floats\n"));
    // A name too long for the column: the description starts on the next line.
    EXPECT_THAT(help, HasSubstr("  --a-very-long-option-name-indeed SOMETHING\n" + std::string(34, ' ') + "Which: word0"));
    // Every word is still there, in order.
    std::string words;
    for (const std::string& line : lines_of(help))
        if (line.find("word") != std::string::npos) words += line;
    EXPECT_THAT(words, HasSubstr("word28"));
}

TEST_F(HelpFormatterTest, ANarrowWidthPutsDescriptionsUnderTheirNames) {
    app.formatter(std::make_shared<orb::cli::HelpFormatter>(40));
    app.add_option("--spp", spp, "Samples per pixel, as many as the render needs to converge");
    const std::string help = app.help();
    EXPECT_THAT(help, HasSubstr("  --spp N\n      Samples per pixel, as many as the\n      render needs to converge\n"));
    for (const std::string& line : lines_of(help)) EXPECT_LE(line.size(), 40u) << line;
}

}  // namespace
