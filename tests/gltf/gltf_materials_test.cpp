// glTF materials -> Orb materials, one sphere per rule (docs/gltf.md).
#include <gtest/gtest.h>

#include "gltf_test_util.h"
#include "orb/scene/error.h"

namespace orb::gltf_test {
namespace {

const Material& material_of(const Scene& scene, const std::string& sphere) {
    return scene.materials.at(sphere_named(scene, sphere).material);
}

void expect_color(const Vec3& got, const Vec3& want) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-7) << "component " << c;
}

class Materials : public ::testing::TestWithParam<std::string> {};

TEST_P(Materials, EachRule) {
    const GltfImportResult result = import_generated("materials" + GetParam());
    const Scene& scene = result.scene;
    ASSERT_EQ(scene.spheres.size(), 7u);

    const Material& diffuse = material_of(scene, "Diffuse");
    EXPECT_EQ(diffuse.type, MaterialType::Diffuse);
    expect_color(diffuse.color, {0.2, 0.4, 0.6});
    expect_color(diffuse.emission, {0, 0, 0});

    // baseColorFactor (0.5,1,1) x mean COLOR_0 (0.4,0.2,0.8); colours are float32.
    const Material& vertex = material_of(scene, "VertexColour");
    EXPECT_EQ(vertex.type, MaterialType::Diffuse);
    expect_color(vertex.color, {0.2, 0.2, 0.8});

    const Material& mirror = material_of(scene, "Mirror");
    EXPECT_EQ(mirror.type, MaterialType::Mirror);
    expect_color(mirror.color, {0.9, 0.8, 0.7});

    const Material& glass = material_of(scene, "Glass");
    EXPECT_EQ(glass.type, MaterialType::Dielectric);
    EXPECT_DOUBLE_EQ(glass.ior, 1.33);
    expect_color(glass.color, {1, 1, 0.9});

    // emissiveFactor (1,0.5,0.25) x emissiveStrength 4.
    const Material& lamp = material_of(scene, "Lamp");
    expect_color(lamp.emission, {4, 2, 1});
    expect_color(lamp.color, {0, 0, 0});

    const Material& textured = material_of(scene, "Textured");
    EXPECT_EQ(textured.type, MaterialType::Diffuse);
    expect_color(textured.color, {0.3, 0.3, 0.3});

    const Material& none = material_of(scene, "NoMaterial");
    EXPECT_EQ(none.type, MaterialType::Diffuse);
    expect_color(none.color, {0.8, 0.8, 0.8});

    // Exactly one warning, naming the file and the texture.
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_EQ(result.warnings[0], generated("materials" + GetParam()) + ": ignored: 1 base-colour texture");
}

INSTANTIATE_TEST_SUITE_P(Gltf, Materials, ::testing::Values(".gltf", "_embedded.gltf", ".glb"));

TEST(GltfMaterials, StrictRefusesTextures) {
    GltfImportOptions strict;
    strict.strict = true;
    EXPECT_THROW(import_generated("materials.gltf", strict), InputError);
}

class Ignored : public ::testing::TestWithParam<std::string> {};

TEST_P(Ignored, OneWarningNamesEverythingDroppedWithCounts) {
    const std::string path = generated("ignored" + GetParam());
    const GltfImportResult result = import_generated("ignored" + GetParam());
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_EQ(result.warnings[0],
              path + ": ignored: 2 base-colour textures, 1 normal texture, 1 transmission texture "
                     "(KHR_materials_transmission), spot cone angles of 2 lights, range of 1 light, "
                     "KHR_materials_clearcoat (2 materials), KHR_materials_sheen (1 material), "
                     "EXT_lights_image_based (required extension)");
    EXPECT_EQ(result.scene.spheres.size(), 6u);  // 4 balls and 2 lights
}

TEST_P(Ignored, StrictRefusesNamingTheFile) {
    GltfImportOptions strict;
    strict.strict = true;
    try {
        import_generated("ignored" + GetParam(), strict);
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(generated("ignored" + GetParam()) + ": ignored: 2 base-colour textures", 0), 0u)
            << message;
        EXPECT_NE(message.find("--strict"), std::string::npos) << message;
    }
}

INSTANTIATE_TEST_SUITE_P(Gltf, Ignored, ::testing::Values(".gltf", "_embedded.gltf", ".glb"));

}  // namespace
}  // namespace orb::gltf_test
