// The JSON form of the canonical scene: defaults, round trips, stable output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
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

// The writer hands the spheres over in pieces of a few thousand, and the
// hash reads those pieces instead of the whole text (ten million spheres
// are 1.4 GB of it): across piece boundaries, the text must read back to
// the scene and the hash must be FNV-1a of exactly that text. 16384 spheres
// end a piece on the last sphere; 40000 end mid-piece.
TEST(SceneJson, ManySpheresWriteAndHashAcrossPieces) {
    for (const std::size_t count : {std::size_t{16384}, std::size_t{40000}}) {
        orb::Scene s = sample_scene();
        for (std::size_t i = s.spheres.size(); i < count; ++i)
            s.spheres.push_back({i % 7 ? "" : "grain " + std::to_string(i),
                                 {0.1 * static_cast<double>(i), 1.0 / static_cast<double>(i + 3), -2.5},
                                 0.01 + 1e-9 * static_cast<double>(i),
                                 static_cast<std::uint32_t>(i % 3)});
        const std::string text = orb::write_scene_json(s);
        EXPECT_EQ(orb::load_scene_json(text, "mem"), s) << count;
        std::uint64_t h = 1469598103934665603ull;
        for (unsigned char b : text) {
            h ^= b;
            h *= 1099511628211ull;
        }
        char hex[17];
        std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
        EXPECT_EQ(orb::scene_content_hash(s), hex) << count;
    }
}

// pbr and rough glass round-trip exactly; the writer adds "roughness" and
// "metallic" only where they belong, so a smooth scene is written as before.
TEST(SceneJson, RoughMaterialsRoundTripAndSmoothOnesKeepTheirForm) {
    orb::Scene s = sample_scene();
    const std::string smooth = orb::write_scene_json(s);
    EXPECT_EQ(smooth.find("roughness"), std::string::npos) << smooth;
    EXPECT_EQ(smooth.find("metallic"), std::string::npos) << smooth;

    orb::Material gold{"gold", orb::MaterialType::Pbr, {1, 0.78, 0.34}, {0, 0, 0}, 1.5};
    gold.roughness = 0.1 + 0.2;  // an awkward double
    gold.metallic = 1;
    orb::Material frosted{"frosted", orb::MaterialType::Dielectric, {1, 1, 1}, {0, 0, 0}, 1.5};
    frosted.roughness = 0.25;
    s.materials.push_back(gold);
    s.materials.push_back(frosted);
    const std::string text = orb::write_scene_json(s);
    EXPECT_EQ(orb::load_scene_json(text, "mem"), s);
    EXPECT_NE(text.find("\"type\": \"pbr\", \"color\": [1, 0.78, 0.34], \"emission\": [0, 0, 0], \"ior\": 1.5, "
                        "\"roughness\": 0.30000000000000004, \"metallic\": 1 }"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("\"type\": \"dielectric\", \"color\": [1, 1, 1], \"emission\": [0, 0, 0], \"ior\": 1.5, "
                        "\"roughness\": 0.25 }"),
              std::string::npos)
        << text;
    EXPECT_NE(orb::scene_content_hash(s), orb::scene_content_hash(sample_scene()));
}

// A pbr material without factors is glTF's default: a fully rough metal.
TEST(SceneJson, PbrDefaultsAreGltfs) {
    const orb::Scene s =
        orb::load_scene_json(read_file(ORB_TEST_DATA_DIR "/scene/valid/rough-materials.json"), "rough-materials.json");
    ASSERT_EQ(s.materials.size(), 6u);
    EXPECT_EQ(s.materials[2].type, orb::MaterialType::Pbr);
    EXPECT_EQ(s.materials[2].metallic, 1.0);
    EXPECT_EQ(s.materials[2].roughness, 1.0);
    EXPECT_EQ(s.materials[0].roughness, 0.3);
    EXPECT_EQ(s.materials[1].metallic, 0.0);
    EXPECT_EQ(s.materials[3].roughness, 0.2);
    EXPECT_EQ(s.materials[4].roughness, 0.0);
    EXPECT_EQ(s.materials[5].roughness, 0.0);  // diffuse: none
}

// The model's own check (what importers end in) keeps the same rules.
TEST(SceneJson, ValidationRejectsParametersAMaterialDoesNotHave) {
    orb::Scene s = sample_scene();
    s.materials[0].roughness = 0.5;  // diffuse
    try {
        orb::validate_scene(s, "mem");
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("materials[0].roughness: a \"diffuse\" material has no roughness"),
                  std::string::npos)
            << e.what();
    }
    s = sample_scene();
    s.materials[1].roughness = std::nan("");
    EXPECT_THROW(orb::validate_scene(s, "mem"), orb::InputError);
    s = sample_scene();
    s.materials[1].metallic = 0.5;  // dielectric
    EXPECT_THROW(orb::validate_scene(s, "mem"), orb::InputError);
    s.materials[1].type = orb::MaterialType::Pbr;
    EXPECT_NO_THROW(orb::validate_scene(s, "mem"));
    s.materials[1].metallic = 1.5;
    EXPECT_THROW(orb::validate_scene(s, "mem"), orb::InputError);
}

// The orthographic height round-trips exactly; a perspective scene is written
// (and hashed) without the key, as before it existed.
TEST(SceneJson, OrthographicHeightRoundTripsAndPerspectiveScenesKeepTheirForm) {
    orb::Scene s = sample_scene();
    const std::string perspective = orb::write_scene_json(s);
    EXPECT_EQ(perspective.find("orthographic_height"), std::string::npos) << perspective;

    s.camera.orthographic_height = 0.1 + 0.2;  // an awkward double
    const std::string text = orb::write_scene_json(s);
    EXPECT_NE(text.find("\"orthographic_height\": 0.30000000000000004"), std::string::npos) << text;
    EXPECT_EQ(orb::load_scene_json(text, "mem"), s);
    EXPECT_NE(orb::scene_content_hash(s), orb::scene_content_hash(sample_scene()));

    const orb::Scene file =
        orb::load_scene_json(read_file(ORB_TEST_DATA_DIR "/scene/valid/orthographic.json"), "orthographic.json");
    EXPECT_EQ(file.camera.orthographic_height, 2.5);
    EXPECT_EQ(orb::load_scene_json(read_file(ORB_TEST_DATA_DIR "/scene/valid/minimal.json"), "minimal.json")
                  .camera.orthographic_height,
              0.0);
}

// Values no JSON text can hold (NaN, infinity) reach validate_scene from
// importers; it names the field.
TEST(SceneJson, ValidationRejectsAnOrthographicHeightThatIsNotALength) {
    for (const double bad : {-1.0, std::nan(""), double(INFINITY), 1e-300, 1e300}) {
        orb::Scene s = sample_scene();
        s.camera.orthographic_height = bad;
        try {
            orb::validate_scene(s, "mem");
            ADD_FAILURE() << "expected an error for " << bad;
        } catch (const orb::InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("mem: camera.orthographic_height: must be 0 (a perspective camera) or in "
                                                  "[1e-18, 1e+18]",
                                                  0),
                      0u)
                << e.what();
        }
    }
}

TEST(SceneJson, SmallptGpuFieldOfView) {
    EXPECT_NEAR(orb::smallptgpu_vfov_deg(), 42.8798, 1e-4);
    EXPECT_NEAR(orb::Camera{}.vfov_deg, orb::smallptgpu_vfov_deg(), 1e-12);
}

}  // namespace
