// orb-import run as a real executable: inputs, outputs, exit codes, messages,
// and the promise that a failed run leaves no file behind and clobbers nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "orb/scene/scene_json.h"
#include "orb/import/scn.h"
#include "import_cli_fixture.h"
#include "run_process.h"

namespace orb {
namespace {

namespace fs = std::filesystem;
using test::ProcessResult;
using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::StartsWith;

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const std::string kCornellPath = std::string(ORB_SCENES_DIR) + "/cornell.scn";

constexpr const char* kGlassWithIor133 = R"({ "format": "orb-scene", "version": 1,
  "camera": { "position": [0, 1, 10], "target": [0, 1, 0] },
  "materials": [ { "name": "water", "type": "dielectric", "color": [1, 1, 1], "ior": 1.33 } ],
  "spheres": [ { "name": "drop", "center": [0, 1, 0], "radius": 1, "material": "water" } ] })";

class OrbImportCli : public test::ImportCliFixture {};

TEST_F(OrbImportCli, ScnFileToOrbJsonOnStdout) {
    const ProcessResult r = run({kCornellPath});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.err, IsEmpty());
    EXPECT_EQ(load_scene_json(r.out, "stdout"), parse_scn(slurp(kCornellPath), "cornell.scn"));
}

TEST_F(OrbImportCli, StdinToStdoutGivesTheSameScene) {
    const ProcessResult from_file = run({kCornellPath});
    const ProcessResult from_stdin = run({"-"}, slurp(kCornellPath));
    EXPECT_EQ(from_stdin.exit_code, 0) << from_stdin.err;
    EXPECT_EQ(from_stdin.out, from_file.out);
}

TEST_F(OrbImportCli, WritesTheOutputFileAndNothingElse) {
    const ProcessResult r = run({kCornellPath, "-o", "cornell.json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.out, IsEmpty());
    EXPECT_EQ(files(), std::vector<std::string>{"cornell.json"});
    EXPECT_EQ(load_scene_json(slurp(dir_ / "cornell.json"), "cornell.json"),
              parse_scn(slurp(kCornellPath), "cornell.scn"));
}

TEST_F(OrbImportCli, RoundTripsScnThroughOrbJsonWithEveryNumberUnchanged) {
    ASSERT_EQ(run({kCornellPath, "-o", "cornell.json"}).exit_code, 0);
    const ProcessResult r = run({"cornell.json", "--to", "scn", "-o", "back.scn"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.err, IsEmpty());  // nothing lost
    const std::string original = slurp(kCornellPath);
    const std::string back = slurp(dir_ / "back.scn");
    EXPECT_EQ(parse_scn(back, "back.scn"), parse_scn(original, "cornell.scn"));
    EXPECT_EQ(back, write_scn(parse_scn(original, "cornell.scn")).text);
}

TEST_F(OrbImportCli, OutputFormatFollowsTheScnExtension) {
    const ProcessResult r = run({kCornellPath, "-o", "copy.scn"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(slurp(dir_ / "copy.scn"), StartsWith("camera 50 45 205.6  50 44.957388 204.6\nsize 9\n"));
    // An explicit --to wins over the extension.
    EXPECT_EQ(run({kCornellPath, "--to", "orb", "-o", "really-json.scn"}).exit_code, 0);
    EXPECT_THAT(slurp(dir_ / "really-json.scn"), StartsWith("{"));
}

TEST_F(OrbImportCli, ScnToStdout) {
    const ProcessResult r = run({"-", "--to", "scn"}, slurp(kCornellPath));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, write_scn(parse_scn(slurp(kCornellPath), "cornell.scn")).text);
}

TEST_F(OrbImportCli, FromOverridesContentDetection) {
    const ProcessResult as_scn = run({"-", "--from", "scn"}, slurp(kCornellPath));
    EXPECT_EQ(as_scn.exit_code, 0) << as_scn.err;
    // Read as Orb JSON, .scn text is a JSON syntax error.
    const ProcessResult as_orb = run({kCornellPath, "--from", "orb"});
    EXPECT_EQ(as_orb.exit_code, 1);
    EXPECT_THAT(as_orb.err, StartsWith("orb-import: error: " + kCornellPath + ":1:"));
    EXPECT_THAT(as_orb.out, IsEmpty());
}

TEST_F(OrbImportCli, LossyScnOutputWarns) {
    write("water.json", kGlassWithIor133);
    const ProcessResult r = run({"water.json", "--to", "scn", "-o", "water.scn"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "orb-import: warning: material 0 ('water') is a dielectric with ior 1.33; "
                     ".scn glass always has ior 1.5\n");
    EXPECT_THAT(slurp(dir_ / "water.scn"), HasSubstr("sphere 1  0 1 0  0 0 0  1 1 1  2\n"));
}

TEST_F(OrbImportCli, QuietSilencesWarnings) {
    write("water.json", kGlassWithIor133);
    const ProcessResult r = run({"water.json", "--to", "scn", "-q"});
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_THAT(r.err, IsEmpty());
    EXPECT_THAT(r.out, StartsWith("camera 0 1 10  0 1 0\n"));
}

TEST_F(OrbImportCli, StrictMakesLossesAnErrorAndWritesNothing) {
    write("water.json", kGlassWithIor133);
    const ProcessResult r = run({"water.json", "--to", "scn", "--strict", "-o", "water.scn"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_THAT(r.err, StartsWith("orb-import: error: writing .scn would lose information (--strict):\n"
                                  "  material 0 ('water') is a dielectric with ior 1.33"));
    EXPECT_EQ(files(), std::vector<std::string>{"water.json"});
    // Strict changes nothing when nothing is lost.
    EXPECT_EQ(run({kCornellPath, "--to", "scn", "--strict", "-o", "ok.scn"}).exit_code, 0);
}

TEST_F(OrbImportCli, StrictErrorsEvenWhenQuiet) {
    write("water.json", kGlassWithIor133);
    const ProcessResult r = run({"water.json", "--to", "scn", "--strict", "-q"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_THAT(r.err, HasSubstr("error:"));
    EXPECT_THAT(r.out, IsEmpty());
}

struct BadInput {
    const char* name;
    const char* bytes;
    const char* expected_message;
};

// Test output names the case rather than dumping the struct's bytes.
void PrintTo(const BadInput& bad, std::ostream* os) { *os << bad.name; }

class OrbImportBadInput : public OrbImportCli, public ::testing::WithParamInterface<BadInput> {};

TEST_P(OrbImportBadInput, FailsCleanlyLeavingNoFileAndClobberingNothing) {
    const BadInput& bad = GetParam();
    write("bad.scn", bad.bytes);
    write("good.json", "precious");

    const ProcessResult fresh = run({"bad.scn", "-o", "out.json"});
    EXPECT_EQ(fresh.exit_code, 1);
    EXPECT_THAT(fresh.err, StartsWith(std::string("orb-import: error: ") + bad.expected_message));
    EXPECT_EQ(std::count(fresh.err.begin(), fresh.err.end(), '\n'), 1) << "one clear message: " << fresh.err;
    EXPECT_THAT(fresh.out, IsEmpty());

    const ProcessResult over_good = run({"bad.scn", "-o", "good.json"});
    EXPECT_EQ(over_good.exit_code, 1);
    EXPECT_EQ(slurp(dir_ / "good.json"), "precious");
    EXPECT_EQ(files(), (std::vector<std::string>{"bad.scn", "good.json"}));  // no temporaries either
}

INSTANTIATE_TEST_SUITE_P(
    EveryErrorClass, OrbImportBadInput,
    ::testing::Values(
        BadInput{"missing_camera", "size 0\n", "bad.scn:1:1: missing camera"},
        BadInput{"size_mismatch", "camera 0 0 9 0 0 0\nsize 2\nsphere 1 0 0 0 0 0 0 1 1 1 0\n",
                 "bad.scn:2:6: expected 2 sphere lines"},
        BadInput{"unknown_material", "camera 0 0 9 0 0 0\nsize 1\nsphere 1 0 0 0 0 0 0 1 1 1 7\n",
                 "bad.scn:3:28: expected material code"},
        BadInput{"non_finite", "camera 0 0 nan 0 0 0\nsize 0\n", "bad.scn:1:12: expected camera position z"},
        BadInput{"radius", "camera 0 0 9 0 0 0\nsize 1\nsphere -1 0 0 0 0 0 0 1 1 1 0\n",
                 "bad.scn:3:8: expected a radius > 0"},
        BadInput{"degenerate_camera", "camera 0 0 9 0 0 9\nsize 0\n", "bad.scn:1:14: expected a camera target"},
        BadInput{"truncated_line", "camera 0 0 9 0 0 0\nsize 1\nsphere 1 0 0 0 0 0", "bad.scn:3:19: expected emission b"},
        BadInput{"trailing_garbage", "camera 0 0 9 0 0 0\nsize 0 !\n", "bad.scn:2:8: expected end of line"},
        BadInput{"binary_junk", "camera 0 0 9 0 0 0\nsize 0\n\x01\x02\x03", "bad.scn:3:1: expected plain ASCII text"},
        BadInput{"absurd_size", "camera 0 0 9 0 0 0\nsize 4000000000\n", "bad.scn:2:6: expected 4000000000 sphere lines"},
        // Doubles the renderer's floats cannot hold, from each importer (docs/scene-format.md, "Limits").
        BadInput{"scn_radius_beyond_float", "camera 0 0 9 0 0 0\nsize 1\nsphere 1e300 0 0 0 0 0 0 1 1 1 0\n",
                 "bad.scn: spheres[0].radius: must be in [1e-18, 1e+18] (the renderer computes in 32-bit floats), got 1e+300"},
        BadInput{"scn_emission_beyond_float",
                 "camera 0 0 9 0 0 0\nsize 2\nsphere 1 0 0 0 0 0 0 1 1 1 0\nsphere 1 0 0 0 1e39 0 0 1 1 1 0\n",
                 "bad.scn: materials[1].emission: each component must be <= 1000000000000 (the renderer computes in "
                 "32-bit floats), got [1e+39, 0, 0]"},
        BadInput{"json_center_beyond_float",
                 R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0, 0, 9], "target": [0, 0, 0] },
                      "materials": [ { "type": "diffuse" } ], "spheres": [ { "center": [0, 0, -1e19], "radius": 1, "material": 0 } ] })",
                 "bad.scn: spheres[0].center: each component must be in [-1e+18, 1e+18] (the renderer computes in "
                 "32-bit floats), got [0, 0, -1e+19]"},
        BadInput{"gltf_camera_beyond_float",
                 R"({ "asset": { "version": "2.0" }, "scene": 0, "scenes": [ { "nodes": [0] } ],
                      "nodes": [ { "camera": 0, "translation": [0, 0, 1e300] } ],
                      "cameras": [ { "type": "perspective", "perspective": { "yfov": 0.7, "znear": 0.1 } } ] })",
                 "bad.scn: camera.position: each component must be in [-1e+18, 1e+18] (the renderer computes in "
                 "32-bit floats), got [0, 0, 1e+300]"},
        BadInput{"empty", "", "bad.scn: empty input"},
        BadInput{"broken_json", "{ \"format\": ", "bad.scn:1:"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST_F(OrbImportCli, BadStdinNamesStdin) {
    const ProcessResult r = run({"-"}, "camera 1 2\n");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_THAT(r.err, StartsWith("orb-import: error: <stdin>:1:11: expected camera position z, got end of line"));
}

TEST_F(OrbImportCli, MissingInputFileIsAFailure) {
    const ProcessResult r = run({"no-such.scn", "-o", "out.json"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_THAT(r.err, StartsWith("orb-import: error: no-such.scn: cannot open"));
    EXPECT_THAT(files(), IsEmpty());
}

TEST_F(OrbImportCli, MissingOutputFolderIsAFailure) {
    const ProcessResult r = run({kCornellPath, "-o", "no/such/dir/out.json"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_THAT(r.err, HasSubstr("does not exist"));
    EXPECT_THAT(files(), IsEmpty());
}

TEST_F(OrbImportCli, UsageErrorsExitWith2) {
    const std::vector<std::vector<std::string>> usages = {
        {},                                    // no input
        {kCornellPath, "--from", "obj"},      // unknown input format
        {kCornellPath, "--to", "gltf"},       // unknown output format
        {kCornellPath, "--bogus"},            // unknown option
        {kCornellPath, "-o", "out.glb"},      // a format orb-import cannot write
        {kCornellPath, kCornellPath},         // two inputs
    };
    for (const auto& args : usages) {
        const ProcessResult r = run(args);
        EXPECT_EQ(r.exit_code, 2) << ::testing::PrintToString(args) << "\n" << r.err;
        EXPECT_THAT(r.err, StartsWith("orb-import: error: ")) << ::testing::PrintToString(args);
        EXPECT_THAT(r.out, IsEmpty());
    }
    EXPECT_THAT(files(), IsEmpty());
}

TEST_F(OrbImportCli, HelpHasExamplesIncludingAPipeline) {
    const ProcessResult r = run({"--help"});
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_THAT(r.out, HasSubstr("Usage: orb-import"));
    EXPECT_THAT(r.out, HasSubstr("--strict"));
    EXPECT_THAT(r.out, HasSubstr("Examples:"));
    EXPECT_THAT(r.out, HasSubstr("orb-import cornell.scn | orb-render - -o - | orb-tonemap - -o cornell.png"));
}

TEST_F(OrbImportCli, VersionNamesTheTool) {
    const ProcessResult r = run({"--version"});
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_THAT(r.out, StartsWith("orb-import (Orb) "));
}

}  // namespace
}  // namespace orb
