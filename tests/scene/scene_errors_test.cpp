// Every problem the loader finds is reported with the source name and the
// JSON path of the offending value.
#include <gtest/gtest.h>

#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"

namespace {

std::string load_error(const std::string& text) {
    try {
        orb::load_scene_json(text, "s.json");
    } catch (const orb::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

const std::string kHead = R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,5], "target": [0,0,0] }, )";

std::string with_bodies(const std::string& materials, const std::string& spheres) {
    return kHead + "\"materials\": [" + materials + "], \"spheres\": [" + spheres + "] }";
}

// One diffuse sphere, animated as `animation` says.
std::string with_animation(const std::string& animation) {
    return kHead + R"("materials": [{ "type": "diffuse" }], "spheres": [{ "center": [0,0,0], "radius": 1, "material": 0 }], "animation": )" +
           animation + " }";
}

struct Case {
    const char* name;
    std::string text;
    std::string expected;  // substring of the message
};

class LoaderErrors : public ::testing::TestWithParam<Case> {};

TEST_P(LoaderErrors, NamesPathAndProblem) {
    const std::string message = load_error(GetParam().text);
    EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
    EXPECT_EQ(message.rfind("s.json:", 0), 0u) << message;
}

const std::string kDiffuse = R"({ "type": "diffuse" })";

INSTANTIATE_TEST_SUITE_P(
    Scene, LoaderErrors,
    ::testing::Values(
        Case{"syntax", "{ \"format\": \"orb-scene\",\n  \"version\": 1,, }", "s.json:2:16: invalid JSON"},
        Case{"empty", "", "s.json:1:1: invalid JSON"},
        Case{"not_object", "[1]", "(root): expected an object"},
        Case{"wrong_format", R"({ "format": "x", "version": 1 })", "format: expected \"orb-scene\""},
        Case{"missing_version", R"({ "format": "orb-scene" })", "missing required key \"version\""},
        Case{"newer_version", R"({ "format": "orb-scene", "version": 7 })", "version: this is a version 7 scene"},
        Case{"unknown_top_key", kHead + R"("materials": [], "spheres": [], "extra": 1 })", "extra: unknown key"},
        Case{"missing_camera", R"({ "format": "orb-scene", "version": 1, "materials": [], "spheres": [] })",
             "missing required key \"camera\""},
        Case{"camera_not_vec3", R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0], "target": [0,0,0] }, "materials": [], "spheres": [] })",
             "camera.position: expected an array of 3 numbers"},
        Case{"camera_degenerate", R"({ "format": "orb-scene", "version": 1, "camera": { "position": [1,1,1], "target": [1,1,1] }, "materials": [], "spheres": [] })",
             "camera.target: must differ from camera.position"},
        Case{"camera_parallel_up", R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,9,0], "target": [0,1,0] }, "materials": [], "spheres": [] })",
             "camera.up: the view direction"},
        Case{"fov", R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,1], "target": [0,0,0], "vfov_deg": 0 }, "materials": [], "spheres": [] })",
             "camera.vfov_deg: must be in (0, 180)"},
        Case{"orthographic_negative", R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,1], "target": [0,0,0], "orthographic_height": -2 }, "materials": [], "spheres": [] })",
             "camera.orthographic_height: must be 0 (a perspective camera) or in [1e-18, 1e+18] (an orthographic view that "
             "many units high) (the renderer computes in 32-bit floats), got -2"},
        Case{"orthographic_not_number", R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,1], "target": [0,0,0], "orthographic_height": "2" }, "materials": [], "spheres": [] })",
             "camera.orthographic_height: expected a number"},
        Case{"render_width", kHead + R"("render": { "width": 0 }, "materials": [], "spheres": [] })",
             "render.width: must be in [1, 65536], got 0"},
        Case{"render_spp_fraction", kHead + R"("render": { "spp": 2.5 }, "materials": [], "spheres": [] })",
             "render.spp: expected an integer"},
        Case{"material_type", with_bodies(R"({ "type": "plastic" })", ""),
             "materials[0].type: expected \"diffuse\", \"mirror\", \"dielectric\" or \"pbr\", got \"plastic\""},
        Case{"roughness_on_mirror", with_bodies(R"({ "type": "mirror", "roughness": 0.3 })", ""),
             "materials[0].roughness: a \"mirror\" material has no roughness (only \"dielectric\" and \"pbr\" "
             "materials have one; a rough metal is \"pbr\" with \"metallic\": 1)"},
        Case{"metallic_on_dielectric", with_bodies(R"({ "type": "dielectric", "metallic": 1 })", ""),
             "materials[0].metallic: a \"dielectric\" material has no metallic (only \"pbr\" materials have one"},
        Case{"roughness_range", with_bodies(kDiffuse + R"(, { "type": "pbr", "roughness": 1.5 })", ""),
             "materials[1].roughness: must be in [0, 1], got 1.5"},
        Case{"metallic_range", with_bodies(R"({ "type": "pbr", "metallic": -0.25 })", ""),
             "materials[0].metallic: must be in [0, 1], got -0.25"},
        Case{"roughness_not_number", with_bodies(R"({ "type": "dielectric", "roughness": "rough" })", ""),
             "materials[0].roughness: expected a number"},
        Case{"material_color_range", with_bodies(kDiffuse + R"(, { "type": "diffuse", "color": [0.5, 1.5, 0] })", ""),
             "materials[1].color: each component must be in [0, 1]"},
        Case{"material_emission_negative", with_bodies(R"({ "type": "diffuse", "emission": [0, 0, -1] })", ""),
             "materials[0].emission: each component must be finite and >= 0"},
        Case{"material_ior", with_bodies(R"({ "type": "dielectric", "ior": -1 })", ""), "materials[0].ior: must be > 0, got -1"},
        Case{"radius_negative", with_bodies(kDiffuse, R"({ "center": [0,0,0], "radius": 1, "material": 0 }, { "center": [0,0,0], "radius": 1, "material": 0 }, { "center": [0,0,0], "radius": 1, "material": 0 }, { "center": [0,0,0], "radius": -2, "material": 0 })"),
             "spheres[3].radius: must be > 0, got -2"},
        Case{"radius_missing", with_bodies(kDiffuse, R"({ "center": [0,0,0], "material": 0 })"),
             "spheres[0]: missing required key \"radius\""},
        Case{"material_out_of_range", with_bodies(kDiffuse, R"({ "center": [0,0,0], "radius": 1, "material": 4 })"),
             "spheres[0].material: must be in [0, 0], got 4"},
        Case{"material_unknown_name", with_bodies(kDiffuse, R"({ "center": [0,0,0], "radius": 1, "material": "gold" })"),
             "spheres[0].material: no material is named \"gold\""},
        Case{"no_materials", with_bodies("", R"({ "center": [0,0,0], "radius": 1, "material": 0 })"),
             "spheres[0].material: refers to a material but \"materials\" is empty"},
        Case{"infinite_number", with_bodies(kDiffuse, R"({ "center": [1e999,0,0], "radius": 1, "material": 0 })"),
             "s.json:1:157: a number overflows a double"},
        Case{"string_number", with_bodies(kDiffuse, R"({ "center": [0,"1",0], "radius": 1, "material": 0 })"),
             "spheres[0].center[1]: expected a number, got string \"1\""},
        // Doubles that the renderer's 32-bit floats cannot hold (scene-format.md, "Limits").
        Case{"radius_too_large", with_bodies(kDiffuse, R"({ "center": [0,0,0], "radius": 1e300, "material": 0 })"),
             "spheres[0].radius: must be in [1e-18, 1e+18] (the renderer computes in 32-bit floats), got 1e+300"},
        Case{"radius_too_small", with_bodies(kDiffuse, R"({ "center": [0,0,0], "radius": 1e-40, "material": 0 })"),
             "spheres[0].radius: must be in [1e-18, 1e+18]"},
        Case{"center_too_far", with_bodies(kDiffuse, R"({ "center": [0,2e18,0], "radius": 1, "material": 0 })"),
             "spheres[0].center: each component must be in [-1e+18, 1e+18] (the renderer computes in 32-bit floats), got [0, 2e+18, 0]"},
        Case{"emission_too_bright", with_bodies(R"({ "type": "diffuse", "emission": [1e39, 0, 0] })", ""),
             "materials[0].emission: each component must be <= 1000000000000 (the renderer computes in 32-bit floats), got [1e+39, 0, 0]"},
        Case{"ior_too_large", with_bodies(R"({ "type": "dielectric", "ior": 1e40 })", ""),
             "materials[0].ior: must be in [1e-18, 1e+18]"},
        Case{"camera_too_far", R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,-1e20], "target": [0,0,0] }, "materials": [], "spheres": [] })",
             "camera.position: each component must be in [-1e+18, 1e+18]"},
        Case{"camera_up_huge", R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,1], "target": [0,0,0], "up": [0,1e300,0] }, "materials": [], "spheres": [] })",
             "camera.up: each component must be in [-1e+18, 1e+18]"},
        Case{"aperture_huge", R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,1], "target": [0,0,0], "aperture": 1e30 }, "materials": [], "spheres": [] })",
             "camera.aperture: must be <= 1e+18"},
        Case{"focus_distance_tiny", R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,1], "target": [0,0,0], "focus_distance": 1e-300 }, "materials": [], "spheres": [] })",
             "camera.focus_distance: must be in [1e-18, 1e+18]"},
        Case{"keyframe_value_huge",
             with_animation(R"({ "nodes": [ { "channels": [ { "path": "translation", "times": [0, 1], "values": [[0,0,0], [0,1e300,0]] } ] } ] })"),
             "animation.nodes[0].channels[0].values[1]: each component must be in [-1e+18, 1e+18] (the renderer computes in 32-bit floats), got 1e+300"},
        Case{"node_scale_huge", with_animation(R"({ "nodes": [ { "scale": [1, 1, -1e20] } ] })"),
             "animation.nodes[0].scale: each component must be in [-1e+18, 1e+18]"},
        Case{"binding_radius_huge",
             with_animation(R"({ "nodes": [ {} ], "spheres": [ { "sphere": 0, "node": 0, "center": [0,0,0], "radius": 1e19 } ] })"),
             "animation.spheres[0].radius: must be in [1e-18, 1e+18]"},
        Case{"sphere_unknown_key", with_bodies(kDiffuse, R"({ "center": [0,0,0], "radius": 1, "material": 0, "colour": 1 })"),
             "spheres[0].colour: unknown key"}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace

// What a message may quote of an input: text as it is, every other byte escaped.
TEST(Printable, KeepsTextAndEscapesEveryOtherByte) {
    EXPECT_EQ(orb::printable("plain text, tab\tand\nline"), "plain text, tab\tand\nline");
    EXPECT_EQ(orb::printable("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80"), "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80");
    EXPECT_EQ(orb::printable(std::string("a\0b\x7f\x1b", 5)), "a\\x00b\\x7F\\x1B");
    EXPECT_EQ(orb::printable("\xff\xfe"), "\\xFF\\xFE");
    EXPECT_EQ(orb::printable("\xc3"), "\\xC3");                    // cut short
    EXPECT_EQ(orb::printable("\xc0\x80"), "\\xC0\\x80");          // overlong
    EXPECT_EQ(orb::printable("\xed\xa0\x80"), "\\xED\\xA0\\x80");  // a surrogate
}
