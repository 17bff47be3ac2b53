// The material types' names, read from ORB_MATERIAL_TABLE
// (libtables/include/orb/tables/material_kinds.h): no list of kinds here.
#include "orb/scene/detail/material_types.h"

#include <vector>

namespace orb {

const char* material_type_name(MaterialType type) {
    switch (type) {
#define ORB_SCENE_NAME_CASE(member, value, name, scn_word, prefix, caster_rule) \
    case MaterialType::member: return name;
        ORB_MATERIAL_TABLE(ORB_SCENE_NAME_CASE)
#undef ORB_SCENE_NAME_CASE
    }
    return "diffuse";  // not reached: every enumerator is a row of the table
}

namespace detail {

std::optional<MaterialType> material_type_from_name(std::string_view name) {
    for (MaterialType type : kMaterialTypes)
        if (name == material_type_name(type)) return type;
    return std::nullopt;
}

const char* material_type_scn_word(MaterialType type) {
    switch (type) {
#define ORB_SCN_WORD_CASE(member, value, name, scn_word, prefix, caster_rule) \
    case MaterialType::member: return scn_word;
        ORB_MATERIAL_TABLE(ORB_SCN_WORD_CASE)
#undef ORB_SCN_WORD_CASE
    }
    return "diffuse";
}

std::string quoted_material_type_names(bool (*select)(MaterialType), const char* last_separator) {
    std::vector<std::string> names;
    for (MaterialType type : kMaterialTypes)
        if (!select || select(type)) names.push_back('"' + std::string(material_type_name(type)) + '"');
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) list += i + 1 == names.size() ? last_separator : ", ";
        list += names[i];
    }
    return list;
}

}  // namespace detail
}  // namespace orb
