// Refuses assets whose geometry is compressed (Draco, meshopt) before tinygltf
// validates them: their accessors have no bufferView, or views into a
// compressed stream, and tinygltf would report that ("accessor[1] invalid
// bufferView") instead of the reason (docs/gltf.md, "Input").
#include <nlohmann/json.hpp>

#include <set>

#include "gltf_internal.h"
#include "orb/scene/error.h"

namespace orb::gltf {
namespace {

// Extensions without which the geometry cannot be read.
const std::set<std::string> kUndecodableExtensions{"KHR_draco_mesh_compression", "EXT_meshopt_compression"};

}  // namespace

void refuse_undecodable_extensions(std::string_view json_text, const std::string& source) {
    // Malformed JSON is left to tinygltf, which explains what is wrong with it.
    const nlohmann::json document = nlohmann::json::parse(json_text.begin(), json_text.end(), nullptr, false);
    if (document.is_discarded() || !document.is_object()) return;
    const auto required = document.find("extensionsRequired");
    if (required == document.end() || !required->is_array()) return;
    for (std::size_t i = 0; i < required->size(); ++i) {
        const nlohmann::json& name = (*required)[i];
        if (name.is_string() && kUndecodableExtensions.count(name.get<std::string>()))
            throw InputError(source + ": extensionsRequired[" + std::to_string(i) + "]: the asset requires " +
                             name.get<std::string>() + ", which Orb cannot decode");
    }
}

}  // namespace orb::gltf
