// Looking material types up by the names and words of ORB_MATERIAL_TABLE, for
// the scene readers and writers (orb::material_type_name is in scene.h).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "orb/scene/scene.h"

namespace orb::detail {

// The type the scene format calls `name` ("dielectric"); none for any other word.
std::optional<MaterialType> material_type_from_name(std::string_view name);

// The word a .scn-derived material name uses for the type ("glass" for a dielectric).
const char* material_type_scn_word(MaterialType type);

// The scene names of the types `select` picks (all when null), quoted, in the
// table's order: "\"diffuse\", \"mirror\", \"dielectric\" or \"pbr\"" with
// last_separator " or ".
std::string quoted_material_type_names(bool (*select)(MaterialType), const char* last_separator);

}  // namespace orb::detail
