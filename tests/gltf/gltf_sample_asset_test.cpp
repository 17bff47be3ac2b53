// A real asset: the Khronos sample MetalRoughSpheresNoTextures
// (tests/data/gltf-sample-assets, CC0), 98 spheres of the metallic-roughness
// model in a 7 x 7 grid per base colour. Every sphere must come in with its
// material's base colour, metallic and roughness exactly as the asset's own
// JSON gives them (read here from the GLB's JSON chunk, apart from the
// importer), and its name must agree with them ("m33%_r66%": metallic 1/3,
// roughness 2/3, as percentages rounded down; "g_" before the gold ones). The four text labels are
// meshes, not spheres: left out with one warning naming them. The asset has
// no light: it gets the default environment. docs/gltf.md shows it rendered.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <span>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "gltf_test_util.h"

namespace orb::gltf_test {
namespace {

const std::string kAsset = std::string(ORB_GLTF_SAMPLE_ASSETS_DIR) +
                           "/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb";

// The GLB's JSON chunk: a 12-byte header, then the chunk's length and type.
nlohmann::json glb_json(const std::string& bytes) {
    std::uint32_t length = 0, type = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    std::memcpy(&type, bytes.data() + 16, 4);
    EXPECT_EQ(type, 0x4E4F534Au);  // "JSON"
    return nlohmann::json::parse(bytes.substr(20, length));
}

using Factors = std::tuple<double, double, double, double, double>;  // r, g, b, metallic, roughness

TEST(GltfSampleAsset, MetalRoughSpheresKeepEveryMaterialFactor) {
    const std::string bytes = read_file(kAsset);
    const nlohmann::json gltf = glb_json(bytes);
    const GltfImportResult result = import_gltf(bytes, kAsset, "", {});
    const Scene& scene = result.scene;

    // What the asset says: the factors of the material of every mesh node.
    std::multiset<Factors> expected;
    std::vector<std::string> labels;
    for (const auto& node : gltf.at("nodes")) {
        if (!node.contains("mesh")) continue;
        const std::string name = node.value("name", "");
        if (name.find('%') == std::string::npos) {
            labels.push_back(name);
            continue;
        }
        const auto& primitive = gltf.at("meshes").at(node.at("mesh").get<int>()).at("primitives").at(0);
        const auto& pbr = gltf.at("materials").at(primitive.at("material").get<int>()).at("pbrMetallicRoughness");
        const auto& c = pbr.at("baseColorFactor");
        expected.insert({c[0].get<double>(), c[1].get<double>(), c[2].get<double>(),
                         pbr.value("metallicFactor", 1.0), pbr.value("roughnessFactor", 1.0)});
    }
    ASSERT_EQ(expected.size(), 98u);
    ASSERT_EQ(labels.size(), 4u);

    // What came in.
    ASSERT_EQ(scene.spheres.size(), 98u + 1u);  // and the default key light, the last
    std::multiset<Factors> imported;
    std::map<std::tuple<double, double, double>, int> per_colour;
    const std::regex percentages(R"((?:g_)?m(\d+)%_r(\d+)%)");  // g_: the gold ones
    for (const Sphere& sphere : std::span(scene.spheres).first(98)) {
        const Material& m = scene.materials.at(sphere.material);
        EXPECT_EQ(m.type, MaterialType::Pbr) << sphere.name;
        imported.insert({m.color[0], m.color[1], m.color[2], m.metallic, m.roughness});
        ++per_colour[{m.color[0], m.color[1], m.color[2]}];
        std::smatch match;
        ASSERT_TRUE(std::regex_match(sphere.name, match, percentages)) << sphere.name;
        const double metallic_percent = std::stod(match[1]), roughness_percent = std::stod(match[2]);
        // The names hold the factors as whole percentages, rounded down.
        EXPECT_GE(100 * m.metallic, metallic_percent - 1e-9) << sphere.name;
        EXPECT_LT(100 * m.metallic, metallic_percent + 1) << sphere.name;
        EXPECT_GE(100 * m.roughness, roughness_percent - 1e-9) << sphere.name;
        EXPECT_LT(100 * m.roughness, roughness_percent + 1) << sphere.name;
    }
    EXPECT_EQ(imported, expected);
    // Two base colours (grey and gold), 49 spheres each: seven metallic steps
    // by seven roughness steps.
    ASSERT_EQ(per_colour.size(), 2u);
    for (const auto& [colour, count] : per_colour) EXPECT_EQ(count, 49);

    // One warning names the four labels; the default environment lights it.
    std::size_t naming = 0;
    for (const std::string& w : result.warnings)
        if (std::all_of(labels.begin(), labels.end(), [&](const std::string& l) { return w.find("'" + l + "'") != std::string::npos; }))
            ++naming;
    EXPECT_EQ(naming, 1u);
    EXPECT_EQ(scene.environment.kind, EnvironmentKind::Color);
    EXPECT_EQ(scene.environment.color, (Vec3{kDefaultEnvironmentRadiance, kDefaultEnvironmentRadiance,
                                             kDefaultEnvironmentRadiance}));
    EXPECT_EQ(scene.spheres.back().name, "default key light");
}

}  // namespace
}  // namespace orb::gltf_test
