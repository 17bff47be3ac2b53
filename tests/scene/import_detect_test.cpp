// Scene files are recognised by their content, not their name.
#include <gtest/gtest.h>

#include "orb/scene/error.h"
#include "orb/scene/import.h"

namespace {

using orb::SceneFormat;

TEST(DetectSceneFormat, ByContent) {
    EXPECT_EQ(orb::detect_scene_format("glTF\x02\0\0\0"), SceneFormat::Glb);
    EXPECT_EQ(orb::detect_scene_format(R"({ "asset": { "version": "2.0" } })"), SceneFormat::GltfJson);
    EXPECT_EQ(orb::detect_scene_format("\xEF\xBB\xBF\n { \"format\": \"orb-scene\", \"version\": 1 }"), SceneFormat::OrbJson);
    EXPECT_EQ(orb::detect_scene_format("camera 0 0 0 0 0 1\nsize 0\n"), SceneFormat::Scn);
    EXPECT_EQ(orb::detect_scene_format("  \n"), SceneFormat::Unknown);
}

TEST(DetectSceneFormat, MalformedJsonGoesToTheReaderThatExplainsIt) {
    EXPECT_EQ(orb::detect_scene_format(R"({ "asset": { "version": "2.0" }, )"), SceneFormat::GltfJson);
    EXPECT_EQ(orb::detect_scene_format(R"({ "format": "orb-scene", )"), SceneFormat::OrbJson);
}

TEST(DetectSceneFormat, NamesRoundTrip) {
    for (SceneFormat f : {SceneFormat::OrbJson, SceneFormat::Scn, SceneFormat::GltfJson, SceneFormat::Glb})
        EXPECT_EQ(orb::scene_format_from_name(orb::scene_format_name(f)), f);
    EXPECT_EQ(orb::scene_format_from_name("obj"), SceneFormat::Unknown);
}

TEST(ImportScene, EmptyInputIsAClearError) {
    try {
        orb::import_scene("", "in.scn", ".");
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("in.scn: empty input"), std::string::npos) << e.what();
    }
}

constexpr const char* kNoSpheres =
    R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,5], "target": [0,0,0] }, "materials": [], "spheres": [] })";

TEST(ImportScene, ASceneWithoutSpheresIsRefusedUnlessAllowed) {
    try {
        orb::import_scene(kNoSpheres, "s.json", ".");
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_STREQ(e.what(),
                     "s.json: no spheres: its \"spheres\" list is empty; --allow-empty accepts a scene without spheres");
    }
    orb::ImportOptions options;
    options.allow_empty = true;
    const auto result = orb::import_scene(kNoSpheres, "s.json", ".", options);
    EXPECT_TRUE(result.scene.spheres.empty());
    EXPECT_TRUE(result.warnings.empty());
    EXPECT_EQ(result.notices, std::vector<std::string>{"s.json: no spheres: its \"spheres\" list is empty"});
}

TEST(ImportScene, AnScnWithoutSpheresIsRefused) {
    try {
        orb::import_scene("camera 0 0 9 0 0 0\nsize 0\n", "s.scn", ".");
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_STREQ(e.what(), "s.scn: no spheres: it lists none (size 0); --allow-empty accepts a scene without spheres");
    }
}

}  // namespace
