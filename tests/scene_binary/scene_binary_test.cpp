// The binary form keeps every number, name and section of a scene exactly.
#include <gtest/gtest.h>

#include "binary_test_scene.h"
#include "orb/import/import.h"
#include "orb/import/importers.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"

namespace orb {
namespace {

TEST(SceneBinary, RoundTripIsExact) {
    const Scene scene = test::every_feature_scene();
    EXPECT_EQ(load_scene_binary(write_scene_binary(scene), "s.orb"), scene);
}

TEST(SceneBinary, JsonToBinaryToJsonIsByteForByteTheSame) {
    const std::string json = write_scene_json(test::every_feature_scene());
    const Scene from_json = load_scene_json(json, "s.json");
    const Scene through_binary = load_scene_binary(write_scene_binary(from_json), "s.orb");
    EXPECT_EQ(write_scene_json(through_binary), json);
}

TEST(SceneBinary, OrthographicCameraRoundTrips) {
    Scene scene = test::every_feature_scene();
    scene.camera.orthographic_height = 1.0 / 3.0;
    const std::string bytes = write_scene_binary(scene);
    EXPECT_NE(bytes.find("\"orthographic_height\":0.3333333333333333"), std::string::npos);
    EXPECT_EQ(load_scene_binary(bytes, "s.orb"), scene);
    // A perspective camera's header has no such key, as before it existed.
    EXPECT_EQ(write_scene_binary(test::every_feature_scene()).find("orthographic_height"), std::string::npos);
}

TEST(SceneBinary, UnnamedSpheresStoreNoNames) {
    Scene scene = test::every_feature_scene();
    for (Sphere& s : scene.spheres) s.name.clear();
    const std::string bytes = write_scene_binary(scene);
    EXPECT_NE(bytes.find("\"sphere_names\":false"), std::string::npos);
    EXPECT_EQ(load_scene_binary(bytes, "s.orb"), scene);
    // Centres, radii and material indices: 36 bytes a sphere, nothing more.
    const std::size_t header = bytes.size() - 36 * scene.spheres.size();
    EXPECT_EQ(header % 8, 0u);
}

TEST(SceneBinary, EmptySceneAndSpecialNumbersRoundTrip) {
    Scene scene;
    scene.camera.target = {0, 0, -1};
    EXPECT_EQ(load_scene_binary(write_scene_binary(scene), "e.orb"), scene);
    scene.materials.push_back({});
    // Awkward doubles within the renderer's float range (validate_scene): a
    // negative zero, a denormal, the largest coordinate and the smallest radius.
    scene.spheres.push_back({"", {-0.0, 5e-324, 1e18}, 1e-18, 0});
    const Scene back = load_scene_binary(write_scene_binary(scene), "e.orb");
    EXPECT_EQ(back, scene);
    EXPECT_TRUE(std::signbit(back.spheres[0].center[0]));
}

TEST(SceneBinary, FormatIsRecognisedByItsMagic) {
    const std::string bytes = write_scene_binary(test::every_feature_scene());
    EXPECT_TRUE(bytes.starts_with(std::string("\x89ORB\r\n\x1a\n", 8)));
    ASSERT_NE(recognise_scene(bytes), nullptr);
    EXPECT_EQ(recognise_scene(bytes)->name, "orb-binary");
    EXPECT_EQ(find_scene_importer("orb-binary"), recognise_scene(bytes));
    EXPECT_EQ(import_scene(bytes, "s.orb", ".").scene, test::every_feature_scene());
}

}  // namespace
}  // namespace orb
