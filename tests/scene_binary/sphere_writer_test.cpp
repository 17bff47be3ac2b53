// write_scene_json writes the spheres directly for speed; its bytes must stay
// exactly those of the generic JSON formatter, which this test rebuilds.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "animation_json.h"
#include "binary_test_scene.h"
#include "orb/scene/detail/json_text.h"
#include "orb/scene/scene_json.h"

namespace orb {
namespace {

using ordered_json = nlohmann::ordered_json;

// The document as the generic writer built it before the direct sphere writer.
std::string generic_json(const Scene& scene) {
    ordered_json document = ordered_json::parse(write_scene_json(Scene{scene.camera, scene.render, scene.materials, {}, {}, scene.environment, {}}));
    ordered_json spheres = ordered_json::array();
    for (const Sphere& s : scene.spheres) {
        ordered_json sphere;
        sphere["name"] = s.name;
        sphere["center"] = ordered_json::array({s.center[0], s.center[1], s.center[2]});
        sphere["radius"] = s.radius;
        sphere["material"] = s.material;
        spheres.push_back(std::move(sphere));
    }
    document["spheres"] = std::move(spheres);
    ordered_json animation = detail::animation_to_json(scene.animation);
    if (!animation.is_null()) document["animation"] = std::move(animation);
    return detail::format_json(document) + "\n";
}

TEST(SphereWriter, SameBytesAsTheGenericFormatter) {
    Scene scene = test::every_feature_scene();
    scene.spheres[1].name = "tab\there \"quoted\" back\\slash \x01 ünïcode";
    scene.spheres[2].center = {-0.0, 1e-7, 1e300};
    scene.spheres[2].radius = 3;
    EXPECT_EQ(write_scene_json(scene), generic_json(scene));
    scene.animation = {};
    EXPECT_EQ(write_scene_json(scene), generic_json(scene));
    scene.spheres.clear();
    EXPECT_EQ(write_scene_json(scene), generic_json(scene));
}

}  // namespace
}  // namespace orb
