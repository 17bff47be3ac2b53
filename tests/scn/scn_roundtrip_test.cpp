// The five SmallptGPU scenes: .scn -> Orb JSON -> .scn keeps every number.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "orb/scene/scene_json.h"
#include "orb/import/scn.h"
#include "scn_test_util.h"

namespace orb {
namespace {

// Every number of a .scn text in order, as strtod reads it (bit patterns, so -0 != 0).
std::vector<std::uint64_t> numbers_of(const std::string& text) {
    std::vector<std::uint64_t> numbers;
    std::istringstream words(text);
    std::string word;
    while (words >> word) {
        if (word == "camera" || word == "size" || word == "sphere") continue;
        char* end = nullptr;
        const double value = std::strtod(word.c_str(), &end);
        EXPECT_EQ(*end, '\0') << "not a number: " << word;
        numbers.push_back(std::bit_cast<std::uint64_t>(value));
    }
    return numbers;
}

// Keywords in order, to check the statement structure survives too.
std::vector<std::string> keywords_of(const std::string& text) {
    std::vector<std::string> keywords;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string first;
        if (words >> first) keywords.push_back(first);
    }
    return keywords;
}

class SharedScene : public ::testing::TestWithParam<const char*> {};

TEST_P(SharedScene, RoundTripsThroughOrbJsonWithEveryNumberUnchanged) {
    const std::string path = std::string(ORB_SCENES_DIR) + "/" + GetParam();
    const std::string original = test::read_file(path);

    const Scene imported = parse_scn(original, path);
    const std::string json = write_scene_json(imported);
    const Scene reloaded = load_scene_json(json, "roundtrip.json");
    EXPECT_EQ(reloaded, imported);

    const ScnWriteResult written = write_scn(reloaded);
    EXPECT_TRUE(written.lossy.empty()) << written.lossy.front();
    EXPECT_EQ(numbers_of(written.text), numbers_of(original)) << written.text;
    EXPECT_EQ(keywords_of(written.text), keywords_of(original));
    // And the written file reads back to the very same scene, names included.
    EXPECT_EQ(parse_scn(written.text, "written.scn"), imported);
    // Writing is deterministic and idempotent.
    EXPECT_EQ(write_scn(parse_scn(written.text, "written.scn")).text, written.text);
}

INSTANTIATE_TEST_SUITE_P(Bucciarelli, SharedScene,
                         ::testing::Values("cornell.scn", "cornell_large.scn", "simple.scn", "caustic.scn",
                                           "caustic3.scn"),
                         [](const auto& info) {
                             std::string name = info.param;
                             return name.substr(0, name.find('.'));
                         });

TEST(SharedScenes, CornellBoxImportsAsExpected) {
    const Scene scene = parse_scn(test::read_file(std::string(ORB_SCENES_DIR) + "/cornell.scn"), "cornell.scn");
    ASSERT_EQ(scene.spheres.size(), 9u);
    // red, green, white, black walls; white mirror; white glass; light
    ASSERT_EQ(scene.materials.size(), 7u);
    EXPECT_EQ(scene.materials[scene.spheres[0].material].name, "red diffuse");
    EXPECT_EQ(scene.materials[scene.spheres[1].material].name, "green diffuse");
    EXPECT_EQ(scene.materials[scene.spheres[3].material].name, "black diffuse");
    EXPECT_EQ(scene.materials[scene.spheres[6].material].type, MaterialType::Mirror);
    EXPECT_EQ(scene.materials[scene.spheres[7].material].type, MaterialType::Dielectric);
    EXPECT_EQ(scene.materials[scene.spheres[8].material].name, "light");
    EXPECT_EQ(scene.materials[scene.spheres[8].material].emission, (Vec3{12, 12, 12}));
    EXPECT_EQ(scene.spheres[2].material, scene.spheres[4].material);  // white walls share one material
    EXPECT_EQ(scene.camera.target, (Vec3{50, 44.957388, 204.6}));
}

TEST(ScnRoundTrip, AwkwardNumbersSurvive) {
    const std::string text =
        "camera 0.1 -0 1e-300  123456789.123456789 5e-324 1e18\n"
        "size 1\n"
        "sphere 1.0000000000000001e-18  100000 -1e18 -2.5e-7  0 1e12 0.3  0.1 0.2 0.30000000000000004  2\n";
    const Scene scene = parse_scn(text, "t.scn");
    const std::string written = write_scn(scene).text;
    EXPECT_EQ(numbers_of(written), numbers_of(text)) << written;
    EXPECT_EQ(parse_scn(written, "w.scn"), scene);
    // Plain decimals where they stay short, exponents where they would not.
    EXPECT_NE(written.find(" 100000 "), std::string::npos) << written;
    EXPECT_NE(written.find(" 1e-300 "), std::string::npos) << written;
}

}  // namespace
}  // namespace orb
