// orb-import writing and reading the binary scene (.orb): by extension or
// --to orb-binary, recognised by its magic, exact round trips through JSON.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"
#include "orb/import/scn.h"
#include "import_cli_fixture.h"
#include "run_process.h"

namespace orb {
namespace {

namespace fs = std::filesystem;
using test::ProcessResult;
using ::testing::IsEmpty;
using ::testing::StartsWith;

const std::string kCornellPath = std::string(ORB_SCENES_DIR) + "/cornell.scn";

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class OrbImportBinaryCli : public test::ImportCliFixture {};

TEST_F(OrbImportBinaryCli, ScnToBinaryToJsonIsExact) {
    ASSERT_EQ(run({kCornellPath, "-o", "cornell.orb"}).exit_code, 0);
    const std::string binary = slurp(dir_ / "cornell.orb");
    EXPECT_TRUE(binary.starts_with(kSceneBinaryMagic));
    const ProcessResult json = run({"cornell.orb", "-o", "cornell.json"});
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const ProcessResult direct = run({kCornellPath});
    EXPECT_EQ(slurp(dir_ / "cornell.json"), direct.out);
    EXPECT_EQ(load_scene_binary(binary, "cornell.orb"), parse_scn(slurp(kCornellPath), "cornell.scn"));
}

TEST_F(OrbImportBinaryCli, ToOrbBinaryOnStdoutAndStdinByMagic) {
    const ProcessResult binary = run({kCornellPath, "--to", "orb-binary"});
    ASSERT_EQ(binary.exit_code, 0) << binary.err;
    EXPECT_TRUE(binary.out.starts_with(kSceneBinaryMagic));
    const ProcessResult json = run({"-"}, binary.out);
    ASSERT_EQ(json.exit_code, 0) << json.err;
    EXPECT_EQ(json.out, run({kCornellPath}).out);
    EXPECT_EQ(run({"-", "--from", "orb-binary", "--to", "orb-binary"}, binary.out).out, binary.out);
}

TEST_F(OrbImportBinaryCli, BrokenBinaryIsOneErrorAndNoOutput) {
    std::string bytes = run({kCornellPath, "--to", "orb-binary"}).out;
    bytes[9] = 7;  // version 7
    std::ofstream(dir_ / "new.orb", std::ios::binary) << bytes;
    const ProcessResult r = run({"new.orb", "-o", "out.json"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "orb-import: error: new.orb: this is a version 1793 binary scene; this Orb reads up to version 2\n");
    EXPECT_EQ(files(), std::vector<std::string>{"new.orb"});
    // A .orb name picks the binary reader even when the magic is gone.
    std::ofstream(dir_ / "text.orb", std::ios::binary) << "camera 0 0 0 0 0 1\n";
    EXPECT_THAT(run({"text.orb"}).err,
                StartsWith("orb-import: error: text.orb: not an Orb binary scene (the file does not start with its magic bytes)"));
}

}  // namespace
}  // namespace orb
