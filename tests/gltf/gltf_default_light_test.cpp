// An asset that brings no light gets the default light (a grey environment
// and a key light), with a notice (never fatal, even under --strict, since
// nothing is lost); one with any light, punctual or emissive, keeps only its
// own; --no-default-light (GltfImportOptions::default_light = false) leaves
// it unlit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gltf_test_util.h"
#include "orb/scene/camera_frame.h"

namespace orb::gltf_test {
namespace {

class DefaultLight : public ::testing::TestWithParam<const char*> {};

TEST_P(DefaultLight, AnAssetWithoutLightGetsAGreyEnvironmentAndAKeyLight) {
    GltfImportOptions strict;
    strict.strict = true;
    const GltfImportResult unlit = import_generated("nested" + std::string(GetParam()), [] {
        GltfImportOptions options;
        options.default_light = false;
        return options;
    }());
    const GltfImportResult result = import_generated("nested" + std::string(GetParam()), strict);
    const Scene& scene = result.scene;
    EXPECT_EQ(scene.environment.kind, EnvironmentKind::Color);
    const double b = kDefaultEnvironmentRadiance;
    EXPECT_EQ(scene.environment.color, (Vec3{b, b, b}));
    // One sphere more: the key light, emissive, the last.
    ASSERT_EQ(scene.spheres.size(), unlit.scene.spheres.size() + 1);
    const Sphere& key = scene.spheres.back();
    const Material& light = scene.materials.at(key.material);
    EXPECT_EQ(light.color, (Vec3{0, 0, 0}));
    // Seen from the centre of the asset's spheres' box at sin(theta) = 1/4, at least twice the box's
    // diagonal away, it gives the irradiance pi L sin^2(theta) = kDefaultKeyIrradiance there.
    Vec3 low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};
    for (const Sphere& s : unlit.scene.spheres)
        for (int c = 0; c < 3; ++c) {
            low[c] = std::min(low[c], s.center[c] - s.radius);
            high[c] = std::max(high[c], s.center[c] + s.radius);
        }
    const Vec3 center = vec3::scaled(vec3::add(low, high), 0.5);
    const Vec3 to_key = vec3::sub(key.center, center);
    EXPECT_NEAR(vec3::length(to_key), 4 * key.radius, 1e-9 * key.radius);
    EXPECT_GE(vec3::length(to_key), 2 * vec3::length(vec3::sub(high, low)) * (1 - 1e-12));
    const double sine = key.radius / vec3::length(to_key);
    EXPECT_NEAR(std::numbers::pi * light.emission[0] * sine * sine, kDefaultKeyIrradiance, 1e-9 * kDefaultKeyIrradiance);
    // From the camera's upper left, and out of its view: the whole sphere lies behind the camera's
    // plane, where no camera ray goes.
    const CameraFrame frame = camera_frame(scene.camera);
    EXPECT_LT(vec3::dot(to_key, frame.right), 0);
    EXPECT_GT(vec3::dot(to_key, frame.up), 0);
    EXPECT_LT(vec3::dot(vec3::sub(key.center, scene.camera.position), frame.forward) + key.radius, 0);
    ASSERT_EQ(result.notices.size(), 1u);
    EXPECT_NE(result.notices[0].find(": the asset has no light (no KHR_lights_punctual light imported, no emissive "
                                     "material); added a grey environment of radiance 0.05 and a key light from the "
                                     "camera's upper left (--no-default-light leaves the scene unlit)"),
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
        const GltfImportResult result = import_generated(asset + std::string(GetParam()), GltfImportOptions{});
        EXPECT_EQ(result.scene.environment.kind, EnvironmentKind::None) << asset;
        EXPECT_TRUE(result.notices.empty()) << asset;
    }
}

INSTANTIATE_TEST_SUITE_P(Gltf, DefaultLight, ::testing::Values(".gltf", "_embedded.gltf", ".glb"));

}  // namespace
}  // namespace orb::gltf_test
