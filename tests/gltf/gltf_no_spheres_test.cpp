// An asset that gives no sphere of its own: import_gltf says why in
// no_spheres (from its record of what it left out), and import_scene, which
// the tools read through, refuses it unless allowed. The stand-ins of lights
// do not count: they show nothing of the asset.
#include <gtest/gtest.h>

#include <string>

#include "gltf_test_util.h"
#include "orb/scene/error.h"
#include "orb/import/import.h"

namespace orb {
namespace {

std::string refusal(const std::string& json, const std::string& source) {
    try {
        import_scene(json, source, ".");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(GltfNoSpheres, LightsAloneAreNoScene) {
    const std::string lamp = R"({ "asset": { "version": "2.0" }, "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": { "KHR_lights_punctual": { "lights": [ { "type": "point", "intensity": 10 } ] } },
        "scenes": [ { "nodes": [0] } ],
        "nodes": [ { "name": "Lamp", "extensions": { "KHR_lights_punctual": { "light": 0 } } } ] })";
    const GltfImportResult result = import_gltf(lamp, "lamp.gltf", ".", {});
    EXPECT_EQ(result.scene.spheres.size(), 1u);  // the light's stand-in
    EXPECT_EQ(result.no_spheres, "the asset has no meshes; only the stand-ins of 1 light are left");
    EXPECT_EQ(refusal(lamp, "lamp.gltf"), "lamp.gltf: no spheres: the asset has no meshes; only the stand-ins of 1 "
                                          "light are left; --allow-empty accepts a scene without spheres");
    ImportOptions allowed;
    allowed.allow_empty = true;
    const ImportResult imported = import_scene(lamp, "lamp.gltf", ".", allowed);
    EXPECT_EQ(imported.scene.spheres.size(), 1u);
    EXPECT_EQ(imported.notices.back(),
              "lamp.gltf: no spheres: the asset has no meshes; only the stand-ins of 1 light are left");
}

TEST(GltfNoSpheres, AnImplicitShapeOtherThanASphereIsNamed) {
    const std::string crate = R"({ "asset": { "version": "2.0" }, "extensionsUsed": ["KHR_implicit_shapes"],
        "extensions": { "KHR_implicit_shapes": { "shapes": [ { "type": "box", "box": { "size": [1, 1, 1] } } ] } },
        "scenes": [ { "nodes": [0] } ],
        "nodes": [ { "name": "Crate", "extensions": { "KHR_implicit_shapes": { "shape": 0 } } } ] })";
    EXPECT_EQ(import_gltf(crate, "crate.gltf", ".", {}).no_spheres, "1 implicit shape is not a sphere (box)");
}

TEST(GltfNoSpheres, AnEmptyAssetSaysSo) {
    EXPECT_EQ(refusal(R"({ "asset": { "version": "2.0" } })", "empty.gltf"),
              "empty.gltf: no spheres: the asset has no meshes; --allow-empty accepts a scene without spheres");
}

TEST(GltfNoSpheres, AnAssetWithASphereSaysNothing) {
    // A ball and a cube: the cube is left out (one warning), the ball imports.
    for (const char* container : gltf_test::kContainers) {
        const GltfImportResult result = gltf_test::import_generated(std::string("non_sphere") + container);
        EXPECT_EQ(result.no_spheres, "") << container;
        EXPECT_EQ(result.scene.spheres.size(), 1u) << container;
    }
}

}  // namespace
}  // namespace orb
