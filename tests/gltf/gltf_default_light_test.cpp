// An asset that brings no light gets the default uniform environment, with a
// notice (never fatal, even under --strict, since nothing is lost); one with
// any light, punctual or emissive, keeps only its own; --no-default-light
// (GltfImportOptions::default_light = false) leaves it unlit.
#include <gtest/gtest.h>

#include "gltf_test_util.h"

namespace orb::gltf_test {
namespace {

class DefaultLight : public ::testing::TestWithParam<const char*> {};

TEST_P(DefaultLight, AnAssetWithoutLightGetsAUniformWhiteEnvironment) {
    GltfImportOptions strict;
    strict.strict = true;
    const GltfImportResult result = import_generated("nested" + std::string(GetParam()), strict);
    EXPECT_EQ(result.scene.environment.kind, EnvironmentKind::Color);
    EXPECT_EQ(result.scene.environment.color, (Vec3{1, 1, 1}));
    EXPECT_EQ(kDefaultEnvironmentRadiance, 1.0);
    ASSERT_EQ(result.notices.size(), 1u);
    EXPECT_NE(result.notices[0].find(": the asset has no light (no KHR_lights_punctual light imported, no emissive "
                                     "material); added a uniform white environment of radiance 1 "
                                     "(--no-default-light leaves the scene unlit)"),
              std::string::npos)
        << result.notices[0];
    for (const std::string& warning : result.warnings) EXPECT_EQ(warning.find("no light"), std::string::npos) << warning;
}

TEST_P(DefaultLight, NoDefaultLightLeavesTheAssetUnlit) {
    GltfImportOptions options;
    options.default_light = false;
    const GltfImportResult result = import_generated("nested" + std::string(GetParam()), options);
    EXPECT_EQ(result.scene.environment.kind, EnvironmentKind::None);
    EXPECT_TRUE(result.notices.empty());
}

TEST_P(DefaultLight, AnAssetWithAnyLightKeepsOnlyItsOwn) {
    for (const char* asset : {"point_light", "materials"}) {  // a punctual light; an emissive material
        const GltfImportResult result = import_generated(asset + std::string(GetParam()));
        EXPECT_EQ(result.scene.environment.kind, EnvironmentKind::None) << asset;
        EXPECT_TRUE(result.notices.empty()) << asset;
    }
}

INSTANTIATE_TEST_SUITE_P(Gltf, DefaultLight, ::testing::Values(".gltf", "_embedded.gltf", ".glb"));

}  // namespace
}  // namespace orb::gltf_test
