// glTF metallic-roughness materials -> Orb's pbr, or dielectric for
// transmissive ones (docs/gltf.md, "Materials").
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gltf_internal.h"
#include "gltf_textures.h"

namespace orb::gltf {
namespace {

// A material becomes glass when at least this share of it transmits: glTF
// mixes the metal (opaque) and the dielectric part by metallic, and only the
// dielectric part transmits, transmissionFactor of it.
constexpr double kTransmissiveThreshold = 0.5;
// A primitive without a material gets Blender's default grey, not glTF's
// default material (which is fully metallic and would import as a mirror).
constexpr double kDefaultGrey = 0.8;

double clamp01(double v) { return std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0; }

// Everything that tells two materials apart but their name.
std::string value_key(const Material& material) {
    char key[256];
    std::snprintf(key, sizeof key, "%d|%.17g,%.17g,%.17g|%.17g,%.17g,%.17g|%.17g|%.17g|%.17g|", int(material.type),
                  material.color[0], material.color[1], material.color[2], material.emission[0], material.emission[1],
                  material.emission[2], material.ior, material.roughness, material.metallic);
    return key;
}

}  // namespace

// Orb's glass is always a solid sphere without absorption: say what of
// KHR_materials_volume (or of its absence, a thin wall) that drops.
void MaterialTable::note_volume(const tinygltf::Material& m, const std::string& label) {
    const tinygltf::Value* volume = extension(m.extensions, "KHR_materials_volume");
    const double thickness = volume ? number_at(*volume, "thicknessFactor").value_or(0.0) : 0.0;
    if (!(thickness > 0.0))
        diagnostics_.lossy(label + ": transmissive and thin-walled (no KHR_materials_volume thickness); "
                                   "rendered as a solid glass sphere");
    const std::optional<double> distance = volume ? number_at(*volume, "attenuationDistance") : std::nullopt;
    if (distance && std::isfinite(*distance))
        diagnostics_.lossy(label + ": KHR_materials_volume attenuation (distance " + std::to_string(*distance) +
                           ") is dropped; Orb's glass does not absorb");
}

std::uint32_t MaterialTable::add(Material material) {
    const std::string full_key = value_key(material) + material.name;
    auto it = by_key_.find(full_key);
    if (it != by_key_.end()) return it->second;
    const auto index = std::uint32_t(scene_.materials.size());
    scene_.materials.push_back(std::move(material));
    by_key_.emplace(full_key, index);
    return index;
}

std::uint32_t MaterialTable::get(int index, const AnimVec3& color_scale, bool vertex_colors,
                                 const TextureValues* textures) {
    Material out;
    if (index < 0) {
        out.name = "default";
        const double base = vertex_colors ? 1.0 : kDefaultGrey;
        for (int c = 0; c < 3; ++c) out.color[c] = clamp01(base * color_scale[c]);
        return add(std::move(out));
    }
    if (std::size_t(index) >= model_.materials.size())
        diagnostics_.fail("material " + std::to_string(index) + " does not exist (there are " +
                          std::to_string(model_.materials.size()) + ")");
    const tinygltf::Material& m = model_.materials[std::size_t(index)];
    const bool first_use = used_.insert(index).second;  // say what is lost once per material
    out.name = m.name.empty() ? "material " + std::to_string(index) : m.name;
    const std::string label = "material '" + out.name + "'";

    // glTF multiplies each factor by its texture (docs/gltf.md, "Textures").
    const bool textured = textures && textures->any();
    const std::vector<double>& base = m.pbrMetallicRoughness.baseColorFactor;
    for (int c = 0; c < 3; ++c) {
        const double factor = base.size() == 4 ? base[std::size_t(c)] : 1.0;
        const double texture = textured && textures->base_color ? (*textures->base_color)[std::size_t(c)] : 1.0;
        out.color[c] = clamp01(factor * texture * color_scale[c]);
    }

    double transmission = 0.0;
    if (const tinygltf::Value* ext = extension(m.extensions, "KHR_materials_transmission"))
        transmission = clamp01(number_at(*ext, "transmissionFactor").value_or(0.0));
    const double metallic =
        clamp01(m.pbrMetallicRoughness.metallicFactor * (textured ? textures->metallic.value_or(1.0) : 1.0));
    out.roughness =
        clamp01(m.pbrMetallicRoughness.roughnessFactor * (textured ? textures->roughness.value_or(1.0) : 1.0));
    if ((1.0 - metallic) * transmission >= kTransmissiveThreshold) {
        out.type = MaterialType::Dielectric;
        out.ior = 1.5;  // the KHR_materials_ior default
        if (const tinygltf::Value* ext = extension(m.extensions, "KHR_materials_ior")) {
            const double ior = number_at(*ext, "ior").value_or(1.5);
            if (std::isfinite(ior) && ior >= 1.0) out.ior = ior;
            else if (first_use)
                diagnostics_.lossy(label + ": KHR_materials_ior.ior " + std::to_string(ior) + " is not >= 1; using 1.5");
        }
        if (first_use) note_volume(m, label);
    } else {
        out.type = MaterialType::Pbr;
        out.metallic = metallic;
    }

    double strength = 1.0;
    if (const tinygltf::Value* ext = extension(m.extensions, "KHR_materials_emissive_strength"))
        strength = number_at(*ext, "emissiveStrength").value_or(1.0);
    for (int c = 0; c < 3; ++c) {
        const double factor = m.emissiveFactor.size() == 3 ? m.emissiveFactor[std::size_t(c)] : 0.0;
        const double texture = textured && textures->emission ? (*textures->emission)[std::size_t(c)] : 1.0;
        const double e = factor * strength * texture;
        if (!std::isfinite(e) || e < 0) {
            diagnostics_.lossy(label + ": emission must be finite and >= 0; using 0");
            out.emission[c] = 0.0;
        } else {
            out.emission[c] = e;
        }
    }

    if (!textured) return add(std::move(out));
    // One Orb material per distinct textured result of this glTF material,
    // shared by every sphere that gets it.
    std::map<std::string, std::uint32_t>& variants = textured_[index];
    const std::string key = value_key(out);
    if (auto it = variants.find(key); it != variants.end()) return it->second;
    out.name += " #" + std::to_string(variants.size() + 1);
    const std::uint32_t added = add(std::move(out));
    variants.emplace(key, added);
    return added;
}

std::uint32_t MaterialTable::emitter(const std::string& name, const Vec3& emission) {
    Material out;
    out.name = name;
    out.emission = emission;
    return add(std::move(out));
}

}  // namespace orb::gltf
