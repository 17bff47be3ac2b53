// Node animation imported from glTF: LINEAR (incl. quaternion slerp through
// a parent), STEP and CUBICSPLINE channels, an animated camera, clamping
// outside the keyframes, and the JSON round trip of the animation section.
#include <gtest/gtest.h>

#include <cmath>

#include "gltf_test_util.h"
#include "orb/scene/animation.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"

namespace orb::gltf_test {
namespace {

constexpr double kTol = 1e-6;  // keyframes are float32

void expect_center(const Scene& scene, const std::string& name, const Vec3& want) {
    const Sphere& s = sphere_named(scene, name);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.center[c], want[c], kTol) << name << " axis " << c;
}

class Animated : public ::testing::TestWithParam<std::string> {
protected:
    void SetUp() override { scene_ = import_generated("animation" + GetParam()).scene; }
    Scene at(double t) const { return scene_at_time(scene_, t); }
    Scene scene_;
};

TEST_P(Animated, MovingThingsAreBoundAndStaticOnesAreNot) {
    ASSERT_FALSE(scene_.animation.empty());
    EXPECT_EQ(scene_.animation.spheres.size(), 4u);
    for (const SphereBinding& b : scene_.animation.spheres) EXPECT_NE(scene_.spheres.at(b.sphere).name, "Static");
    EXPECT_GE(scene_.animation.camera_node, 0);
    EXPECT_DOUBLE_EQ(scene_.animation.start_time(), 0.0);
    EXPECT_DOUBLE_EQ(scene_.animation.end_time(), 2.0);
}

TEST_P(Animated, LinearTranslationAndClamping) {
    expect_center(at(0.5), "Linear", {0.5, 0, 0});
    expect_center(at(1.5), "Linear", {1, 1, 0});
    expect_center(at(-1.0), "Linear", {0, 0, 0});  // before the first key: the first value
    expect_center(at(5.0), "Linear", {1, 2, 0});   // after the last key: the last value
}

TEST_P(Animated, SlerpOfAParentMovesItsChild) {
    // Arm turns from identity to 90 degrees about +y; its child sits at (2,0,0).
    expect_center(at(0.0), "ArmBall", {2, 0, 0});
    expect_center(at(0.5), "ArmBall", {std::sqrt(2.0), 0, -std::sqrt(2.0)});  // 45 degrees: slerp, not lerp
    expect_center(at(1.0 / 3.0), "ArmBall", {2 * std::cos(M_PI / 6), 0, -2 * std::sin(M_PI / 6)});
    expect_center(at(1.0), "ArmBall", {0, 0, -2});
}

TEST_P(Animated, StepScaleHoldsUntilTheNextKey) {
    EXPECT_NEAR(sphere_named(at(0.99), "Step").radius, 0.5, kTol);
    EXPECT_NEAR(sphere_named(at(1.0), "Step").radius, 1.0, kTol);
    EXPECT_NEAR(sphere_named(at(1.5), "Step").radius, 1.0, kTol);
    EXPECT_NEAR(sphere_named(at(2.5), "Step").radius, 1.5, kTol);
    expect_center(at(1.5), "Step", {0, 10, 0});
}

TEST_P(Animated, CubicSplineUsesTangentsScaledByTheInterval) {
    // Keys at 0 and 2: value (0,-10,0) out-tangent (1,0,0); in-tangent (3,0,0) value (4,-10,0).
    // At s = 0.5: 0.5*0 + 0.125*2*1 + 0.5*4 - 0.125*2*3 = 1.5.
    expect_center(at(1.0), "Cubic", {1.5, -10, 0});
    // At s = 0.25: h10 = 0.140625, h01 = 0.15625, h11 = -0.046875 -> 0.28125 + 0.625 - 0.28125.
    expect_center(at(0.5), "Cubic", {0.625, -10, 0});
    expect_center(at(2.0), "Cubic", {4, -10, 0});
}

TEST_P(Animated, CameraFollowsItsNodeAndStaticSpheresStay) {
    const Scene half = at(0.5);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(half.camera.position[c], (Vec3{0, 0, 15})[c], kTol);
    EXPECT_NEAR(half.camera.target[2] - half.camera.position[2], scene_.camera.target[2] - scene_.camera.position[2],
                kTol);
    expect_center(half, "Static", {0, 0, -10});
    EXPECT_TRUE(half.animation.empty()) << "the scene at a time is static";
}

TEST_P(Animated, RoundTripsThroughJson) {
    const std::string text = write_scene_json(scene_);
    EXPECT_NE(text.find("\"CUBICSPLINE\""), std::string::npos);
    const Scene back = load_scene_json(text, "animation.json");
    EXPECT_EQ(back, scene_);
    EXPECT_EQ(scene_at_time(back, 0.7), at(0.7));
}

TEST(GltfAnimation, ABrokenChannelCostsItsMotionNotTheScene) {
    // The sampler's input accessor does not exist; the sphere still imports, static.
    const std::string text = R"({"asset":{"version":"2.0"},
      "extensions":{"KHR_implicit_shapes":{"shapes":[{"type":"sphere","sphere":{"radius":1}}]}},
      "nodes":[{"name":"Ball","extensions":{"KHR_implicit_shapes":{"shape":0}}}],
      "animations":[{"samplers":[{"input":5,"output":6}],"channels":[{"sampler":0,"target":{"node":0,"path":"translation"}}]}],
      "scenes":[{"nodes":[0]}]})";
    const GltfImportResult result = import_gltf(text, "broken.gltf", "", without_default_light());
    ASSERT_EQ(result.scene.spheres.size(), 1u);
    EXPECT_TRUE(result.scene.animation.empty());
    EXPECT_TRUE(any_warning_contains(result, "animation 0 channel 0 input: accessor 5 does not exist; the channel is ignored"));
    GltfImportOptions strict;
    strict.strict = true;
    EXPECT_THROW(import_gltf(text, "broken.gltf", "", strict), InputError);
}

class Clips : public ::testing::TestWithParam<std::string> {};

TEST_P(Clips, TheFirstClipPlaysAndTheOthersAreNamed) {
    const GltfImportResult result = import_generated("clips" + GetParam());
    expect_center(scene_at_time(result.scene, 1.0), "Ball", {0, 1, 0});  // "Rise" alone
    ASSERT_EQ(result.warnings.size(), 1u);
    // Named by its file, as every warning of an asset is.
    const std::string file = "clips" + GetParam() + ": ";
    ASSERT_NE(result.warnings[0].find(file), std::string::npos) << result.warnings[0];
    EXPECT_EQ(result.warnings[0].substr(result.warnings[0].find(file) + file.size()),
              "animation 0 'Rise' is imported; the other clips are left out: animation 1 'Slide' "
              "(--animation NAME|INDEX picks one)");
    GltfImportOptions strict;
    strict.strict = true;
    EXPECT_THROW(import_generated("clips" + GetParam(), strict), InputError);
}

TEST_P(Clips, AnimationPicksOneByNameOrIndex) {
    for (const char* key : {"Slide", "1"}) {
        GltfImportOptions options;
        options.animation = key;
        options.strict = true;  // choosing a clip loses nothing
        const GltfImportResult result = import_generated("clips" + GetParam(), options);
        expect_center(scene_at_time(result.scene, 1.0), "Ball", {2, 0, 0});
        expect_center(scene_at_time(result.scene, 0.5), "Ball", {1, 0, 0});
        EXPECT_TRUE(result.warnings.empty()) << key;
    }
    GltfImportOptions missing;
    missing.animation = "Walk";
    try {
        import_generated("clips" + GetParam(), missing);
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--animation Walk: no such animation (there are 2: animation 0 'Rise', "
                                             "animation 1 'Slide')"),
                  std::string::npos)
            << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Gltf, Animated, ::testing::Values(".gltf", "_embedded.gltf", ".glb"));
INSTANTIATE_TEST_SUITE_P(Gltf, Clips, ::testing::Values(".gltf", "_embedded.gltf", ".glb"));

}  // namespace
}  // namespace orb::gltf_test
