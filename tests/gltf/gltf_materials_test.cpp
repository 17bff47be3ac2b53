// glTF materials -> Orb materials, one sphere per rule (docs/gltf.md).
#include <gtest/gtest.h>

#include "gltf_test_util.h"
#include "orb/scene/error.h"

namespace orb::gltf_test {
namespace {

// Without an image decoder (as here: libscene alone) the textures Orb can
// read are ignored too, and the warning says why.
constexpr const char* kNoDecoder = " (textures are read only when the importer is given an image decoder)";

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
    ASSERT_EQ(scene.spheres.size(), 10u);

    // Metallic-roughness is Orb's pbr; glTF's roughnessFactor defaults to 1.
    const Material& diffuse = material_of(scene, "Diffuse");
    EXPECT_EQ(diffuse.type, MaterialType::Pbr);
    expect_color(diffuse.color, {0.2, 0.4, 0.6});
    expect_color(diffuse.emission, {0, 0, 0});
    EXPECT_EQ(diffuse.metallic, 0.0);
    EXPECT_EQ(diffuse.roughness, 1.0);

    // baseColorFactor (0.5,1,1) x mean COLOR_0 (0.4,0.2,0.8); colours are float32.
    const Material& vertex = material_of(scene, "VertexColour");
    EXPECT_EQ(vertex.type, MaterialType::Pbr);
    expect_color(vertex.color, {0.2, 0.2, 0.8});

    const Material& metal = material_of(scene, "Metal");
    EXPECT_EQ(metal.type, MaterialType::Pbr);
    expect_color(metal.color, {0.9, 0.8, 0.7});
    EXPECT_EQ(metal.metallic, 1.0);
    EXPECT_EQ(metal.roughness, 0.25);

    const Material& glass = material_of(scene, "Glass");
    EXPECT_EQ(glass.type, MaterialType::Dielectric);
    EXPECT_DOUBLE_EQ(glass.ior, 1.33);
    EXPECT_EQ(glass.roughness, 0.0);
    EXPECT_EQ(glass.metallic, 0.0);
    expect_color(glass.color, {1, 1, 0.9});

    // Rough transmission keeps its roughness; KHR_materials_ior absent: 1.5.
    const Material& rough_glass = material_of(scene, "RoughGlass");
    EXPECT_EQ(rough_glass.type, MaterialType::Dielectric);
    EXPECT_EQ(rough_glass.ior, 1.5);
    EXPECT_NEAR(rough_glass.roughness, 0.3, 1e-7);

    // Only the dielectric part, 1 - metallic, transmits: 0.4 of it is not glass.
    const Material& mostly_metal = material_of(scene, "MostlyMetalGlass");
    EXPECT_EQ(mostly_metal.type, MaterialType::Pbr);
    EXPECT_NEAR(mostly_metal.metallic, 0.6, 1e-7);
    EXPECT_EQ(mostly_metal.roughness, 0.5);

    const Material& plastic = material_of(scene, "Plastic");
    EXPECT_EQ(plastic.type, MaterialType::Pbr);
    expect_color(plastic.color, {1, 0, 0});
    EXPECT_EQ(plastic.metallic, 0.0);
    EXPECT_EQ(plastic.roughness, 0.5);

    // emissiveFactor (1,0.5,0.25) x emissiveStrength 4.
    const Material& lamp = material_of(scene, "Lamp");
    expect_color(lamp.emission, {4, 2, 1});
    expect_color(lamp.color, {0, 0, 0});

    const Material& textured = material_of(scene, "Textured");
    EXPECT_EQ(textured.type, MaterialType::Pbr);
    expect_color(textured.color, {0.3, 0.3, 0.3});

    const Material& none = material_of(scene, "NoMaterial");
    EXPECT_EQ(none.type, MaterialType::Diffuse);
    expect_color(none.color, {0.8, 0.8, 0.8});

    // Exactly one warning, naming the file and the texture.
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_EQ(result.warnings[0], generated("materials" + GetParam()) + ": ignored: 1 base-colour texture" +
                                      kNoDecoder);
}

INSTANTIATE_TEST_SUITE_P(Gltf, Materials, ::testing::Values(".gltf", "_embedded.gltf", ".glb"));

// Orb's glass is a solid sphere that does not absorb: a thin wall and an
// absorbing volume are each named once per material, and --strict refuses them.
TEST(GltfMaterials, GlassVolumesOrbCannotRenderAreNamed) {
    const GltfImportResult result = import_generated("glass_volumes.gltf");
    ASSERT_EQ(result.scene.spheres.size(), 3u);
    for (const Sphere& sphere : result.scene.spheres)
        EXPECT_EQ(result.scene.materials.at(sphere.material).type, MaterialType::Dielectric) << sphere.name;
    ASSERT_EQ(result.warnings.size(), 2u);
    EXPECT_NE(result.warnings[0].find("material 'ThinWall': transmissive and thin-walled"), std::string::npos)
        << result.warnings[0];
    EXPECT_NE(result.warnings[1].find("material 'Tinted': KHR_materials_volume attenuation"), std::string::npos)
        << result.warnings[1];
    GltfImportOptions strict;
    strict.strict = true;
    EXPECT_THROW(import_generated("glass_volumes.gltf", strict), InputError);
}

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
                     "EXT_lights_image_based (required extension)" +
                  std::string(kNoDecoder));
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
