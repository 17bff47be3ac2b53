// The scene's environment: its JSON form (written only when present), the
// loader's messages, the checks on attached texels, the content hash over
// the texels, and what counts as light.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdio>

#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"

namespace {

using orb::Environment;
using orb::EnvironmentImage;
using orb::EnvironmentKind;

orb::Scene ball() {
    orb::Scene s;
    s.camera.position = {0, 0, 5};
    s.camera.target = {0, 0, 0};
    s.materials.push_back({"grey", orb::MaterialType::Diffuse, {0.5, 0.5, 0.5}, {0, 0, 0}, 1.5});
    s.spheres.push_back({"ball", {0, 0, 0}, 1, 0});
    return s;
}

orb::Scene with_color(const orb::Vec3& color) {
    orb::Scene s = ball();
    s.environment.kind = EnvironmentKind::Color;
    s.environment.color = color;
    return s;
}

orb::Scene with_map(const std::string& path, double intensity, double rotation_deg) {
    orb::Scene s = ball();
    s.environment.kind = EnvironmentKind::Map;
    s.environment.map = path;
    s.environment.intensity = intensity;
    s.environment.rotation_deg = rotation_deg;
    return s;
}

std::shared_ptr<const EnvironmentImage> image(int width, int height, float value) {
    auto result = std::make_shared<EnvironmentImage>();
    result->width = width;
    result->height = height;
    result->rgb.assign(std::size_t(width) * height * 3, value);
    return result;
}

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const orb::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(EnvironmentJson, RoundTripsExactly) {
    for (const orb::Scene& s : {with_color({0.5, 1, 2e3}), with_map("maps/sky.exr", 2.5, -90), with_map("/abs/a b.exr", 0, 1e-3)}) {
        const std::string text = orb::write_scene_json(s);
        EXPECT_EQ(orb::load_scene_json(text, "s.json"), s) << text;
        EXPECT_EQ(orb::write_scene_json(orb::load_scene_json(text, "s.json")), text);
    }
}

TEST(EnvironmentJson, IsWrittenAfterRender) {
    const std::string color = orb::write_scene_json(with_color({1, 2, 3}));
    EXPECT_NE(color.find("\"render\": { \"width\": 640, \"height\": 480, \"spp\": 64, \"max_depth\": 6 },\n"
                         "  \"environment\": { \"color\": [1, 2, 3] },\n  \"materials\""),
              std::string::npos)
        << color;
    const std::string map = orb::write_scene_json(with_map("sky.exr", 1, 0));
    EXPECT_NE(map.find("\"environment\": { \"map\": \"sky.exr\", \"intensity\": 1, \"rotation_deg\": 0 },"),
              std::string::npos)
        << map;
}

TEST(EnvironmentJson, ASceneWithoutOneIsWrittenAsBefore) {
    const std::string text = orb::write_scene_json(ball());
    EXPECT_EQ(text.find("environment"), std::string::npos);
}

TEST(EnvironmentJson, MapDefaultsAreIntensityOneAndNoTurn) {
    const orb::Scene s = orb::load_scene_json(
        R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,5], "target": [0,0,0] },
             "environment": { "map": "sky.exr" }, "materials": [], "spheres": [] })",
        "s.json");
    EXPECT_EQ(s.environment.kind, EnvironmentKind::Map);
    EXPECT_EQ(s.environment.map, "sky.exr");
    EXPECT_EQ(s.environment.intensity, 1.0);
    EXPECT_EQ(s.environment.rotation_deg, 0.0);
    EXPECT_EQ(s.environment.image, nullptr);
}

struct Case {
    const char* name;
    std::string environment;
    std::string expected;
};

class EnvironmentErrors : public ::testing::TestWithParam<Case> {};

TEST_P(EnvironmentErrors, NameThePathAndTheProblem) {
    const Case& c = GetParam();
    const std::string text = R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,5], "target": [0,0,0] }, "environment": )" +
                             c.environment + R"(, "materials": [], "spheres": [] })";
    const std::string message = error_of([&] { orb::load_scene_json(text, "s.json"); });
    EXPECT_EQ(message.rfind("s.json: ", 0), 0u) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Loader, EnvironmentErrors,
    ::testing::Values(
        Case{"not_object", R"("sky.exr")", "environment: expected an object, got string"},
        Case{"empty", "{}", "environment: expected \"color\" (a uniform radiance) or \"map\""},
        Case{"both", R"({ "color": [1, 1, 1], "map": "a.exr" })", "environment: has both \"color\" and \"map\""},
        Case{"color_size", R"({ "color": [1, 1] })", "environment.color: expected an array of 3 numbers"},
        Case{"color_negative", R"({ "color": [1, -1, 1] })", "environment.color: each component must be finite, >= 0"},
        Case{"color_beyond_float", R"({ "color": [1e13, 1, 1] })", "environment.color: each component must be finite, >= 0 and <= 1000000000000"},
        Case{"color_with_intensity", R"({ "color": [1, 1, 1], "intensity": 2 })", "environment.intensity: applies to a \"map\""},
        Case{"map_not_string", R"({ "map": 3 })", "environment.map: expected a string, got number 3"},
        Case{"map_empty", R"({ "map": "" })", "environment.map: must name an EXR file"},
        Case{"intensity_negative", R"({ "map": "a.exr", "intensity": -1 })", "environment.intensity: must be finite, >= 0"},
        Case{"rotation_not_number", R"({ "map": "a.exr", "rotation_deg": "90" })", "environment.rotation_deg: expected a number"},
        Case{"unknown_key", R"({ "map": "a.exr", "rotation": 90 })", "environment.rotation: unknown key (expected one of: map, intensity, rotation_deg)"}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

TEST(EnvironmentTexels, AreCheckedWithThePathOfTheMap) {
    orb::Scene s = with_map("sky.exr", 1, 0);
    s.environment.image = image(4, 2, 1.0f);
    EXPECT_NO_THROW(orb::validate_scene(s, "s.json"));

    const auto with_texel = [&](float value, double intensity) {
        orb::Scene bad = with_map("sky.exr", intensity, 0);
        auto texels = std::make_shared<EnvironmentImage>(*image(4, 2, 1.0f));
        texels->rgb[3 * (1 * 4 + 2) + 1] = value;  // texel (2, 1), G
        bad.environment.image = texels;
        return error_of([&] { orb::validate_scene(bad, "s.json"); });
    };
    EXPECT_EQ(with_texel(NAN, 1), "s.json: environment.map: \"sky.exr\": texel (2, 1) channel G is NaN; an environment map holds finite radiance >= 0");
    EXPECT_EQ(with_texel(-0.5f, 1), "s.json: environment.map: \"sky.exr\": texel (2, 1) channel G is negative (-0.5); radiance is >= 0");
    EXPECT_EQ(with_texel(INFINITY, 1), "s.json: environment.map: \"sky.exr\": texel (2, 1) channel G is infinite; an environment map holds finite radiance >= 0");
    EXPECT_NE(with_texel(2e9f, 1e3).find("texel (2, 1) channel G is 2000000000, times intensity 1000 above 1000000000000"), std::string::npos);
    EXPECT_EQ(with_texel(2e9f, 1.0), "(no error)");

    orb::Scene short_image = with_map("sky.exr", 1, 0);
    auto texels = std::make_shared<EnvironmentImage>(*image(4, 2, 1.0f));
    texels->rgb.pop_back();
    short_image.environment.image = texels;
    EXPECT_NE(error_of([&] { orb::validate_scene(short_image, "s.json"); }).find("do not fill 4x2 RGB"), std::string::npos);
}

// 64-bit FNV-1a, written out again here, over the JSON text and then the
// texels as the header documents them.
std::string fnv_hex(const std::string& text, const EnvironmentImage* texels) {
    std::uint64_t h = 1469598103934665603ull;
    const auto add = [&](unsigned char b) {
        h ^= b;
        h *= 1099511628211ull;
    };
    for (unsigned char b : text) add(b);
    if (texels) {
        const auto add32 = [&](std::uint32_t v) {
            for (int shift = 0; shift < 32; shift += 8) add(static_cast<unsigned char>(v >> shift));
        };
        add32(std::uint32_t(texels->width));
        add32(std::uint32_t(texels->height));
        for (float f : texels->rgb) add32(std::bit_cast<std::uint32_t>(f));
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

TEST(EnvironmentHash, CoversTheMapsTexels) {
    orb::Scene s = with_map("sky.exr", 1, 0);
    const std::string without_texels = orb::scene_content_hash(s);
    EXPECT_EQ(without_texels, fnv_hex(orb::write_scene_json(s), nullptr));
    s.environment.image = image(4, 2, 1.0f);
    const std::string with_texels = orb::scene_content_hash(s);
    EXPECT_EQ(with_texels, fnv_hex(orb::write_scene_json(s), s.environment.image.get()));
    EXPECT_NE(with_texels, without_texels);

    // The same file name with one texel changed is another scene.
    auto edited = std::make_shared<EnvironmentImage>(*s.environment.image);
    edited->rgb[5] = 1.5f;
    orb::Scene other = s;
    other.environment.image = edited;
    EXPECT_NE(orb::scene_content_hash(other), with_texels);
    EXPECT_NE(other, s);
    // Equal content in another allocation is the same scene.
    other.environment.image = std::make_shared<EnvironmentImage>(*s.environment.image);
    EXPECT_EQ(orb::scene_content_hash(other), with_texels);
    EXPECT_EQ(other, s);
}

TEST(EnvironmentHash, AVersion1SceneHashesItsJsonAsBefore) {
    const orb::Scene s = ball();
    EXPECT_EQ(orb::scene_content_hash(s), fnv_hex(orb::write_scene_json(s), nullptr));
}

TEST(SceneHasLight, CountsEmittersAndEnvironmentsThatAreNotBlack) {
    orb::Scene s = ball();
    EXPECT_FALSE(orb::scene_has_light(s));
    EXPECT_TRUE(orb::scene_has_light(with_color({0, 0, 0.1})));
    EXPECT_FALSE(orb::scene_has_light(with_color({0, 0, 0})));
    EXPECT_TRUE(orb::scene_has_light(with_map("sky.exr", 1, 0)));  // not loaded yet: assumed to light
    EXPECT_FALSE(orb::scene_has_light(with_map("sky.exr", 0, 0)));
    orb::Scene black = with_map("sky.exr", 1, 0);
    black.environment.image = image(2, 1, 0.0f);
    EXPECT_FALSE(orb::scene_has_light(black));
    s.materials.push_back({"lamp", orb::MaterialType::Diffuse, {0, 0, 0}, {1, 1, 1}, 1.5});
    EXPECT_FALSE(orb::scene_has_light(s));  // an emissive material no sphere uses
    s.spheres.push_back({"lamp", {0, 3, 0}, 0.5, 1});
    EXPECT_TRUE(orb::scene_has_light(s));
}

}  // namespace
