// The one "ignored: ..." warning per asset: everything the imported content
// uses that Orb drops (docs/gltf.md, "What is ignored").
#include <algorithm>
#include <set>

#include "gltf_internal.h"

namespace orb::gltf {
namespace {

// Material extensions whose values Orb reads (the rest are dropped whole).
const std::set<std::string> kReadMaterialExtensions{"KHR_materials_transmission", "KHR_materials_ior",
                                                    "KHR_materials_volume", "KHR_materials_emissive_strength"};
// Asset-level extensions Orb reads, or that change nothing Orb renders.
const std::set<std::string> kReadExtensions{"KHR_lights_punctual",    "KHR_mesh_quantization",
                                            "EXT_mesh_gpu_instancing", "KHR_implicit_shapes",
                                            "KHR_physics_rigid_bodies"};
// Extensions that only change textures: reported as the textures they belong to.
const std::set<std::string> kTextureExtensions{"KHR_texture_transform", "KHR_texture_basisu", "EXT_texture_webp",
                                               "EXT_texture_avif", "MSFT_texture_dds"};

std::string counted(std::size_t count, const std::string& singular, const std::string& plural) {
    return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

bool is_texture_key(const std::string& key) {
    return key.size() > 7 && key.compare(key.size() - 7, 7, "Texture") == 0;
}

}  // namespace

void IgnoredFeatures::add_material(const tinygltf::Material& material, bool textures_read) {
    const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
    const int core[kCoreTextureKinds] = {pbr.baseColorTexture.index, pbr.metallicRoughnessTexture.index,
                                         material.normalTexture.index, material.occlusionTexture.index,
                                         material.emissiveTexture.index};
    // Base colour, metallic-roughness and emissive are read given a decoder.
    const bool readable[kCoreTextureKinds] = {true, true, false, false, true};
    for (std::size_t k = 0; k < kCoreTextureKinds; ++k) {
        if (core[k] < 0 || (readable[k] && textures_read)) continue;
        ++core_textures_[k];
        if (readable[k]) unread_for_want_of_decoder_ = true;
    }
    for (const auto& [name, value] : material.extensions) {
        if (!kReadMaterialExtensions.count(name)) {
            ++material_extensions_[name];
            continue;
        }
        // Read extensions may still carry textures (transmissionTexture, ...).
        if (value.IsObject())
            for (const std::string& key : value.Keys())
                if (is_texture_key(key))
                    ++extension_textures_[key.substr(0, key.size() - 7) + " texture|" + name];
    }
}

std::string IgnoredFeatures::summary(const tinygltf::Model& model) const {
    std::vector<std::string> items;
    static const char* const kCoreNames[kCoreTextureKinds] = {"base-colour", "metallic-roughness", "normal",
                                                               "occlusion", "emissive"};
    for (std::size_t k = 0; k < kCoreTextureKinds; ++k)
        if (core_textures_[k] > 0)
            items.push_back(counted(core_textures_[k], std::string(kCoreNames[k]) + " texture",
                                    std::string(kCoreNames[k]) + " textures"));
    for (const auto& [key, count] : extension_textures_) {
        const std::size_t bar = key.find('|');
        const std::string kind = key.substr(0, bar), extension = key.substr(bar + 1);
        items.push_back(counted(count, kind, kind + "s") + " (" + extension + ")");
    }
    if (spot_cones_ > 0) items.push_back("spot cone angles of " + counted(spot_cones_, "light", "lights"));
    if (ranges_ > 0) items.push_back("range of " + counted(ranges_, "light", "lights"));
    for (const auto& [name, count] : material_extensions_)
        items.push_back(name + " (" + counted(count, "material", "materials") + ")");
    // Asset-level extensions: material ones were counted per material above.
    std::set<std::string> extensions(model.extensionsUsed.begin(), model.extensionsUsed.end());
    extensions.insert(model.extensionsRequired.begin(), model.extensionsRequired.end());
    for (const std::string& name : extensions) {
        if (kReadExtensions.count(name) || kTextureExtensions.count(name) || kReadMaterialExtensions.count(name) ||
            material_extensions_.count(name))
            continue;
        const bool required =
            std::find(model.extensionsRequired.begin(), model.extensionsRequired.end(), name) !=
            model.extensionsRequired.end();
        items.push_back(name + (required ? " (required extension)" : " (extension)"));
    }
    if (items.empty()) return "";
    std::string text = "ignored: ";
    for (std::size_t i = 0; i < items.size(); ++i) text += (i ? ", " : "") + items[i];
    if (unread_for_want_of_decoder_) text += " (textures are read only when the importer is given an image decoder)";
    return text;
}

}  // namespace orb::gltf
