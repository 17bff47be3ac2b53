// orb-import and the environment: a relative map path is rewritten so that
// the written scene names the same file from where it is written; .scn
// output drops the environment with a warning (an error under --strict);
// --environment sets one from the command line, checked before any input is read.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "import_cli_fixture.h"
#include "orb/import/import.h"
#include "orb/scene/scene_json.h"

namespace orb {
namespace {

namespace fs = std::filesystem;
using test::ProcessResult;
using ::testing::HasSubstr;

std::string scene_with_map(const std::string& map) {
    return R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0, 0, 5], "target": [0, 0, 0] },
  "environment": { "map": ")" + map + R"(", "intensity": 2 },
  "materials": [ { "type": "diffuse" } ], "spheres": [ { "center": [0, 0, 0], "radius": 1, "material": 0 } ] })";
}

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class OrbImportEnvironment : public test::ImportCliFixture {};

TEST_F(OrbImportEnvironment, RelativeMapPathsFollowTheOutput) {
    fs::create_directories(dir_ / "scenes");
    fs::create_directories(dir_ / "out" / "deep");
    write("scenes/scene.json", scene_with_map("../skies/sky.exr"));

    // Into another folder: the path from there to skies/sky.exr.
    ProcessResult r = run({"scenes/scene.json", "-o", "out/deep/copy.json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(load_scene_json(slurp(dir_ / "out/deep/copy.json"), "copy.json").environment.map, "../../skies/sky.exr");

    // To stdout: relative to the current directory, where orb-render - resolves it.
    r = run({"scenes/scene.json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(load_scene_json(r.out, "stdout").environment.map, "skies/sky.exr");

    // Next to the input: unchanged, and the binary form is rebased the same way.
    r = run({"scenes/scene.json", "-o", "scenes/again.json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(load_scene_json(slurp(dir_ / "scenes/again.json"), "again.json").environment.map, "../skies/sky.exr");
    r = run({"scenes/scene.json", "-o", "out/scene.orb"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string bytes = slurp(dir_ / "out/scene.orb");
    EXPECT_EQ(import_scene(bytes, "scene.orb", "").scene.environment.map, "../skies/sky.exr");
}

TEST_F(OrbImportEnvironment, AbsoluteMapPathsStayAsTheyAre) {
    fs::create_directories(dir_ / "out");
    write("scene.json", scene_with_map("/data/skies/sky.exr"));
    const ProcessResult r = run({"scene.json", "-o", "out/copy.json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(load_scene_json(slurp(dir_ / "out/copy.json"), "copy.json").environment.map, "/data/skies/sky.exr");
}

TEST_F(OrbImportEnvironment, ScnOutputDropsTheEnvironmentWithAWarning) {
    write("scene.json", scene_with_map("sky.exr"));
    ProcessResult r = run({"scene.json", "--to", "scn", "-o", "scene.scn"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr("orb-import: warning: the environment light is dropped; SmallptGPU has none"));
    EXPECT_TRUE(fs::exists(dir_ / "scene.scn"));

    r = run({"scene.json", "--to", "scn", "--strict", "-o", "strict.scn"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_THAT(r.err, HasSubstr("the environment light is dropped"));
    EXPECT_FALSE(fs::exists(dir_ / "strict.scn"));
}

// The first bytes of an OpenEXR file: orb-import checks them, orb-render reads the rest.
const std::string kExrMagic("\x76\x2f\x31\x01", 4);

TEST_F(OrbImportEnvironment, ColourOptionReplacesTheScenesEnvironment) {
    write("scene.json", scene_with_map("sky.exr"));
    ProcessResult r = run({"scene.json", "--environment", "0.5,0.25,1"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Environment environment = load_scene_json(r.out, "stdout").environment;
    EXPECT_EQ(environment.kind, EnvironmentKind::Color);
    EXPECT_EQ(environment.color, (Vec3{0.5, 0.25, 1}));

    // One value is grey; the intensity multiplies it.
    r = run({"scene.json", "--environment", "0.5", "--environment-intensity", "3"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    environment = load_scene_json(r.out, "stdout").environment;
    EXPECT_EQ(environment.color, (Vec3{1.5, 1.5, 1.5}));
}

TEST_F(OrbImportEnvironment, MapOptionIsRelativeToTheCurrentFolderAndFollowsTheOutput) {
    fs::create_directories(dir_ / "skies");
    fs::create_directories(dir_ / "out" / "deep");
    write("skies/studio.exr", kExrMagic + std::string(60, '\0'));
    write("scene.json", scene_with_map("sky.exr"));
    const ProcessResult r = run({"scene.json", "--environment", "skies/studio.exr", "--environment-intensity", "2",
                                 "--environment-rotation", "90", "-o", "out/deep/lit.json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Environment environment = load_scene_json(slurp(dir_ / "out/deep/lit.json"), "lit.json").environment;
    EXPECT_EQ(environment.kind, EnvironmentKind::Map);
    EXPECT_EQ(environment.map, "../../skies/studio.exr");
    EXPECT_EQ(environment.intensity, 2);
    EXPECT_EQ(environment.rotation_deg, 90);
}

TEST_F(OrbImportEnvironment, BadEnvironmentsAreOneMessageAndNoOutput) {
    write("scene.json", scene_with_map("sky.exr"));
    write("sky.hdr", "#?RADIANCE\n");
    const struct {
        std::vector<std::string> args;
        std::string message;
    } cases[] = {
        {{"--environment", "missing.exr"}, "orb-import: error: --environment missing.exr: no such file"},
        {{"--environment", "sky.hdr"}, "orb-import: error: --environment sky.hdr: not an OpenEXR file"},
        {{"--environment", "1,2"}, "a colour is one value or three (R,G,B), got 2"},
        {{"--environment", "-1,0,0"}, "radiance must be finite, >= 0 and <= 1e12"},
        {{"--environment", "1", "--environment-intensity", "1e13"}, "--environment-intensity: must be finite"},
        {{"--environment", "1", "--environment-rotation", "inf"}, "--environment-rotation: must be a finite angle"},
    };
    for (const auto& c : cases) {
        std::vector<std::string> args{"scene.json", "-o", "lit.json"};
        args.insert(args.end(), c.args.begin(), c.args.end());
        const ProcessResult r = run(args);
        EXPECT_EQ(r.exit_code, 1) << c.message;
        EXPECT_THAT(r.err, HasSubstr(c.message));
        EXPECT_FALSE(fs::exists(dir_ / "lit.json")) << c.message;
    }
}

}  // namespace
}  // namespace orb
