// The material kinds are one table (ORB_MATERIAL_TABLE, material_kinds.h):
// the scene model's names, and docs/orb-scene.schema.json that documents them,
// must say the same, so a row added to the table cannot leave the schema behind.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <string>
#include <vector>

#include "orb/scene/error.h"
#include "orb/scene/scene.h"
#include "orb/scene/scene_json.h"

namespace {

using nlohmann::json;

json read_schema() {
    std::ifstream in(ORB_SCENE_SCHEMA);
    EXPECT_TRUE(in) << "cannot open " << ORB_SCENE_SCHEMA;
    return json::parse(in);
}

std::vector<std::string> table_names(bool (*select)(orb::MaterialType) = nullptr) {
    std::vector<std::string> names;
    for (orb::MaterialType type : orb::kMaterialTypes)
        if (!select || select(type)) names.push_back(orb::material_type_name(type));
    return names;
}

bool lacks_roughness(orb::MaterialType type) { return !orb::has_roughness(type); }
bool lacks_metallic(orb::MaterialType type) { return !orb::has_metallic(type); }

const json& material_schema(const json& schema) { return schema.at("properties").at("materials").at("items"); }

// The types an "allOf" rule forbids `key` for: { "if": type in [...], "then": not required [key] }.
std::vector<std::string> forbidden_for(const json& material, const std::string& key) {
    for (const json& rule : material.at("allOf"))
        if (rule.at("then").at("not").at("required") == json::array({key}))
            return rule.at("if").at("properties").at("type").at("enum").get<std::vector<std::string>>();
    ADD_FAILURE() << "the schema has no rule forbidding \"" << key << "\"";
    return {};
}

TEST(MaterialKinds, SchemaTypeEnumIsTheTablesNames) {
    const json schema = read_schema();
    EXPECT_EQ(material_schema(schema).at("properties").at("type").at("enum").get<std::vector<std::string>>(),
              table_names());
}

TEST(MaterialKinds, SchemaForbidsParametersExactlyWhereTheLoaderDoes) {
    const json material = material_schema(read_schema());
    EXPECT_EQ(forbidden_for(material, "roughness"), table_names(lacks_roughness));
    EXPECT_EQ(forbidden_for(material, "metallic"), table_names(lacks_metallic));
}

std::string scene_with_material_type(const std::string& type) {
    return R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,5], "target": [0,0,0] },
                "materials": [ { "type": ")" + type + R"(" } ], "spheres": [] })";
}

TEST(MaterialKinds, EveryTableNameLoadsAndWritesBack) {
    for (orb::MaterialType type : orb::kMaterialTypes) {
        const orb::Scene scene = orb::load_scene_json(scene_with_material_type(orb::material_type_name(type)), "m.json");
        ASSERT_EQ(scene.materials.size(), 1u);
        EXPECT_EQ(scene.materials[0].type, type);
        EXPECT_EQ(orb::load_scene_json(orb::write_scene_json(scene), "again.json"), scene);
    }
}

TEST(MaterialKinds, AnUnknownTypeIsRefusedNamingEveryKind) {
    try {
        orb::load_scene_json(scene_with_material_type("plastic"), "m.json");
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        const std::string message = e.what();
        for (const std::string& name : table_names())
            EXPECT_NE(message.find('"' + name + '"'), std::string::npos) << message;
    }
}

}  // namespace
