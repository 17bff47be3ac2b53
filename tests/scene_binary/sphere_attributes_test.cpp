// Per-sphere colours and properties (orb/scene/sphere_attributes.h) in both
// forms of the scene, their checks, and their share of the content hash.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "binary_test_scene.h"
#include "orb/scene/animation.h"
#include "orb/scene/content_hash.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"

namespace orb {
namespace {

// every_feature_scene with a colour per sphere, a numeric and a categorical property.
Scene attributed_scene() {
    Scene scene = test::every_feature_scene();
    const std::size_t n = scene.spheres.size();
    SphereAttributes& a = scene.sphere_attributes;
    for (std::size_t i = 0; i < n; ++i) {
        a.colors.push_back(static_cast<float>(i) / static_cast<float>(n));
        a.colors.push_back(0.1f);
        a.colors.push_back(i % 2 ? 1.0f : 0.0f);
    }
    SphereProperty temperature{"temperature", {}, {}};
    SphereProperty element{"element", {}, {"C", "O", "Fé"}};
    for (std::size_t i = 0; i < n; ++i) {
        temperature.values.push_back(-273.15f + 1e-3f * static_cast<float>(i * i));
        element.values.push_back(static_cast<float>(i % 3));
    }
    a.properties = {temperature, element};
    return scene;
}

std::string validation_error(const Scene& scene) {
    try {
        validate_scene(scene, "s.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(SphereAttributes, JsonRoundTripIsExact) {
    const Scene scene = attributed_scene();
    const std::string text = write_scene_json(scene);
    EXPECT_NE(text.find("\"sphere_colors\": [\n    [0, 0.1, 0],\n    [0.02, 0.1, 1],\n"), std::string::npos);
    EXPECT_NE(text.find("{ \"name\": \"element\", \"labels\": [\"C\", \"O\", \"Fé\"], \"values\": [0, 1, 2, 0,"),
              std::string::npos);
    EXPECT_EQ(load_scene_json(text, "s.json"), scene);
}

TEST(SphereAttributes, ScenesWithoutThemAreWrittenAsBefore) {
    const Scene scene = test::every_feature_scene();
    const std::string text = write_scene_json(scene);
    EXPECT_EQ(text.find("sphere_colors"), std::string::npos);
    EXPECT_EQ(text.find("sphere_properties"), std::string::npos);
    // ... and their hash is the hash of that text, as it always was.
    EXPECT_EQ(scene_content_hash(scene), content_hash_hex(text));
    // A version 1 binary file, byte for byte what an Orb without attributes wrote.
    const std::string bytes = write_scene_binary(scene);
    EXPECT_EQ(bytes[8], 1);
    EXPECT_EQ(bytes.find("sphere_colors"), std::string::npos);
}

TEST(SphereAttributes, BinaryRoundTripIsExactAndKeepsValuesOutOfTheHeader) {
    const Scene scene = attributed_scene();
    const std::string bytes = write_scene_binary(scene);
    EXPECT_EQ(bytes[8], 2);  // container version 2
    EXPECT_NE(bytes.find("\"sphere_colors\":true"), std::string::npos);
    EXPECT_NE(bytes.find("\"sphere_properties\":[{\"name\":\"temperature\"},{\"name\":\"element\",\"labels\":"),
              std::string::npos);
    EXPECT_EQ(load_scene_binary(bytes, "s.orb"), scene);
    // The arrays are binary: 5 floats a sphere at the end of the file, on 8 bytes.
    const std::size_t n = scene.spheres.size();
    Scene without = scene;
    without.sphere_attributes = {};
    EXPECT_LE(bytes.size(), write_scene_binary(without).size() + 200 + 8 + 20 * n);
    EXPECT_EQ((bytes.size() - 20 * n) % 8, 0u);
    // JSON -> binary -> JSON keeps the text.
    const std::string json = write_scene_json(scene);
    EXPECT_EQ(write_scene_json(load_scene_binary(write_scene_binary(load_scene_json(json, "s.json")), "s.orb")), json);
}

TEST(SphereAttributes, OnlyPropertiesOrOnlyColoursRoundTrip) {
    Scene colours = attributed_scene();
    colours.sphere_attributes.properties.clear();
    EXPECT_EQ(load_scene_binary(write_scene_binary(colours), "s.orb"), colours);
    EXPECT_EQ(load_scene_json(write_scene_json(colours), "s.json"), colours);
    Scene properties = attributed_scene();
    properties.sphere_attributes.colors.clear();
    EXPECT_EQ(load_scene_binary(write_scene_binary(properties), "s.orb"), properties);
    EXPECT_EQ(load_scene_json(write_scene_json(properties), "s.json"), properties);
}

TEST(SphereAttributes, BinaryErrorsNameTheProblem) {
    const std::string bytes = write_scene_binary(attributed_scene());
    try {
        load_scene_binary(bytes.substr(0, bytes.size() - 4), "a.orb");
        FAIL() << "a truncated file loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("a.orb: truncated: the header says 50 spheres with 5 attribute floats each"),
                  std::string::npos)
            << e.what();
    }
    // A version 1 file knows no attribute keys.
    std::string old = bytes;
    old[8] = 1;
    const std::size_t at = old.find("\"version\":2");
    ASSERT_NE(at, std::string::npos);
    old[at + 10] = '1';
    try {
        load_scene_binary(old, "a.orb");
        FAIL() << "a version 1 file with attribute keys loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("a version 2 key in a version 1 file"), std::string::npos) << e.what();
    }
    // A colour out of range in the arrays gets validate_scene's message.
    Scene scene = attributed_scene();
    std::string bad = write_scene_binary(scene);
    const std::size_t colours_at = bad.size() - 20 * scene.spheres.size();
    const float two = 2.0f;
    std::memcpy(&bad[colours_at + 4 * 7], &two, 4);  // sphere 2's green
    try {
        load_scene_binary(bad, "a.orb");
        FAIL() << "a colour of 2 loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("a.orb: sphere_colors[2]: each component must be in [0, 1], got [0.04, 2, 0]"),
                  std::string::npos)
            << e.what();
    }
}

TEST(SphereAttributes, ValidationNamesTheArrayAndSphere) {
    Scene scene = attributed_scene();
    scene.sphere_attributes.colors.resize(3 * 49);
    EXPECT_EQ(validation_error(scene), "s.json: sphere_colors: has 49 colours, the scene has 50 spheres (one colour per sphere, or none)");
    scene = attributed_scene();
    scene.sphere_attributes.colors[3 * 4 + 2] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NE(validation_error(scene).find("s.json: sphere_colors[4]: each component must be in [0, 1]"), std::string::npos);
    scene = attributed_scene();
    scene.sphere_attributes.colors[0] = -0.5f;
    EXPECT_NE(validation_error(scene).find("s.json: sphere_colors[0]: each component must be in [0, 1], got [-0.5"),
              std::string::npos);
    scene = attributed_scene();
    scene.sphere_attributes.properties[0].values[9] = std::numeric_limits<float>::infinity();
    EXPECT_EQ(validation_error(scene), "s.json: sphere_properties[0].values[9]: expected a finite number (or null: no value)");
    scene = attributed_scene();
    scene.sphere_attributes.properties[0].values[9] = orb::kNoValue;  // a sphere without a value: valid
    EXPECT_EQ(validation_error(scene), "(no error)");
    scene = attributed_scene();
    scene.sphere_attributes.properties[0].values.pop_back();
    EXPECT_EQ(validation_error(scene),
              "s.json: sphere_properties[0].values: has 49 values, the scene has 50 spheres (one value per sphere)");
    scene = attributed_scene();
    scene.sphere_attributes.properties[1].values[5] = 3;
    EXPECT_EQ(validation_error(scene), "s.json: sphere_properties[1].values[5]: expected an index into the 3 labels (a "
                                       "whole number in [0, 2]), got 3");
    scene = attributed_scene();
    scene.sphere_attributes.properties[1].values[5] = 0.5f;
    EXPECT_NE(validation_error(scene).find("got 0.5"), std::string::npos);
    scene = attributed_scene();
    scene.sphere_attributes.properties[1].name = "temperature";
    EXPECT_EQ(validation_error(scene), "s.json: sphere_properties[1].name: \"temperature\" names an earlier property too");
    scene = attributed_scene();
    scene.sphere_attributes.properties[0].name.clear();
    EXPECT_EQ(validation_error(scene), "s.json: sphere_properties[0].name: must not be empty");
}

TEST(SphereAttributes, JsonReaderErrorsNameThePath) {
    const std::string head = R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,5], "target": [0,0,0] },
        "materials": [{ "type": "diffuse" }], "spheres": [{ "center": [0,0,0], "radius": 1, "material": 0 }], )";
    auto error = [&](const std::string& tail) {
        try {
            load_scene_json(head + tail + " }", "s.json");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_EQ(error(R"("sphere_colors": [[1, 0]])"), "s.json: sphere_colors[0]: expected an array of 3 numbers, got array [1,0]");
    EXPECT_EQ(error(R"("sphere_colors": [[1, 0, 1e300]])"), "s.json: sphere_colors[0][2]: does not fit a 32-bit float, got 1e+300");
    EXPECT_EQ(error(R"("sphere_properties": [{ "name": "t" }])"), "s.json: sphere_properties[0]: missing required key \"values\"");
    EXPECT_EQ(error(R"("sphere_properties": [{ "name": "t", "labels": [], "values": [0] }])"),
              "s.json: sphere_properties[0].labels: must not be empty (leave it out for a numeric property)");
    EXPECT_EQ(error(R"("sphere_colors": [[1, 0, 0.5]])"), "(no error)");
}

TEST(SphereAttributes, AnimatedSpheresKeepTheirColours) {
    const Scene scene = attributed_scene();  // sphere 3 is bound to a spinning node
    ASSERT_FALSE(scene.animation.empty());
    const Scene posed = scene_at_time(scene, 0.5);
    EXPECT_NE(posed.spheres[3].center, scene.spheres[3].center);
    EXPECT_EQ(posed.sphere_attributes, scene.sphere_attributes);
    validate_scene(posed, "posed");
}

TEST(SphereAttributes, HashFollowsEveryColourAndValue) {
    const Scene scene = attributed_scene();
    const std::string hash = scene_content_hash(scene);
    EXPECT_EQ(scene_content_hash(load_scene_binary(write_scene_binary(scene), "s.orb")), hash);
    Scene changed = scene;
    changed.sphere_attributes.colors[3 * 40 + 1] = std::nextafter(0.1f, 1.0f);
    EXPECT_NE(scene_content_hash(changed), hash);
    changed = scene;
    changed.sphere_attributes.properties[1].labels[2] = "Fe";
    EXPECT_NE(scene_content_hash(changed), hash);
    changed = scene;
    changed.sphere_attributes.properties[0].values[0] += 1;
    EXPECT_NE(scene_content_hash(changed), hash);
    changed = scene;
    changed.sphere_attributes.colors.clear();
    EXPECT_NE(scene_content_hash(changed), hash);
    EXPECT_NE(scene_content_hash(test::every_feature_scene()), hash);
}

}  // namespace
}  // namespace orb
