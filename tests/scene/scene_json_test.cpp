// The JSON form of the canonical scene: defaults, round trips, stable output.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"

namespace {

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

orb::Scene sample_scene() {
    orb::Scene s;
    s.camera.position = {50, 52, 295.6};
    s.camera.target = {50, 51.957388, 294.6};
    s.camera.vfov_deg = orb::smallptgpu_vfov_deg();
    s.render = {320, 240, 16, 6};
    s.materials.push_back({"red", orb::MaterialType::Diffuse, {0.75, 0.25, 0.25}, {0, 0, 0}, 1.5});
    s.materials.push_back({"glass", orb::MaterialType::Dielectric, {0.999, 0.999, 0.999}, {0, 0, 0}, 1.33});
    s.materials.push_back({"lamp \"quoted\" \u00e9", orb::MaterialType::Diffuse, {0, 0, 0}, {12, 12, 12}, 1.5});
    s.spheres.push_back({"left wall", {1e5 + 1, 40.8, 81.6}, 1e5, 0});
    s.spheres.push_back({"ball", {27, 16.5, 47}, 16.5, 1});
    s.spheres.push_back({"", {0.1 + 0.2, 1.0 / 3.0, -0.0}, 1.1 * 1e-18, 2});  // awkward doubles (the radius near its lower limit)
    return s;
}

TEST(SceneJson, RoundTripIsExact) {
    const orb::Scene s = sample_scene();
    const std::string text = orb::write_scene_json(s);
    EXPECT_EQ(orb::load_scene_json(text, "mem"), s);
}

TEST(SceneJson, WriterIsStable) {
    const std::string once = orb::write_scene_json(sample_scene());
    const std::string twice = orb::write_scene_json(orb::load_scene_json(once, "mem"));
    EXPECT_EQ(once, twice);
}

TEST(SceneJson, WriterPutsOneSpherePerLineInFixedKeyOrder) {
    const std::string text = orb::write_scene_json(sample_scene());
    EXPECT_EQ(text.rfind("{\n  \"format\": \"orb-scene\",\n  \"version\": 1,\n  \"camera\": ", 0), 0u) << text;
    EXPECT_NE(text.find("\n    { \"name\": \"left wall\", \"center\": [100001, 40.8, 81.6], \"radius\": 100000, \"material\": 0 }"),
              std::string::npos)
        << text;
    EXPECT_EQ(text.back(), '\n');
}

TEST(SceneJson, DefaultsApplyToOptionalKeys) {
    const orb::Scene s = orb::load_scene_json(read_file(ORB_TEST_DATA_DIR "/scene/valid/minimal.json"), "minimal.json");
    const orb::Camera defaults;
    EXPECT_EQ(s.camera.up, defaults.up);
    EXPECT_EQ(s.camera.vfov_deg, defaults.vfov_deg);
    EXPECT_EQ(s.camera.aperture, 0.0);
    EXPECT_EQ(s.camera.focus_distance, 1.0);
    EXPECT_EQ(s.render, orb::RenderSettings{});
    EXPECT_TRUE(s.materials.empty());
    EXPECT_TRUE(s.spheres.empty());
}

TEST(SceneJson, MaterialsResolveByNameOrIndex) {
    const orb::Scene s = orb::load_scene_json(read_file(ORB_TEST_DATA_DIR "/scene/valid/full.json"), "full.json");
    ASSERT_EQ(s.spheres.size(), 4u);
    EXPECT_EQ(s.spheres[0].material, 0u);  // "white"
    EXPECT_EQ(s.spheres[1].material, 1u);  // 1
    EXPECT_EQ(s.spheres[2].material, 2u);  // "chrome"
    EXPECT_EQ(s.materials[3].emission, (orb::Vec3{12, 12, 12}));
    EXPECT_EQ(s.materials[1].type, orb::MaterialType::Dielectric);
    EXPECT_EQ(s.render.max_depth, 8);
    EXPECT_EQ(s.camera.aperture, 0.5);
}

TEST(SceneJson, ContentHashFollowsContent) {
    orb::Scene a = sample_scene();
    orb::Scene b = a;
    EXPECT_EQ(orb::scene_content_hash(a), orb::scene_content_hash(b));
    EXPECT_EQ(orb::scene_content_hash(a).size(), 16u);
    b.spheres[1].radius = std::nextafter(b.spheres[1].radius, 100.0);
    EXPECT_NE(orb::scene_content_hash(a), orb::scene_content_hash(b));
}

TEST(SceneJson, SmallptGpuFieldOfView) {
    EXPECT_NEAR(orb::smallptgpu_vfov_deg(), 42.8798, 1e-4);
    EXPECT_NEAR(orb::Camera{}.vfov_deg, orb::smallptgpu_vfov_deg(), 1e-12);
}

}  // namespace
