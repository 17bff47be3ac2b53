// Writes the binary scene: preamble, JSON header, padded raw sphere arrays.
#include <nlohmann/json.hpp>

#include "animation_json.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"
#include "scene_binary_layout.h"

namespace orb {
namespace {

bool any_sphere_named(const Scene& scene) {
    for (const Sphere& sphere : scene.spheres)
        if (!sphere.name.empty()) return true;
    return false;
}

// Everything but the spheres, as JSON; the scene part is the canonical JSON
// form of the scene without its spheres, so the two forms share one reader.
std::string header_json(const Scene& scene, bool names, std::uint32_t version) {
    Scene without_spheres;
    without_spheres.camera = scene.camera;
    without_spheres.render = scene.render;
    without_spheres.environment = scene.environment;
    without_spheres.materials = scene.materials;
    nlohmann::ordered_json header;
    header["format"] = "orb-scene-binary";
    header["version"] = version;
    header["sphere_count"] = scene.spheres.size();
    header["sphere_names"] = names;
    const SphereAttributes& attributes = scene.sphere_attributes;
    if (!attributes.empty()) {
        // What the attribute arrays after the names hold: their values stay binary.
        header["sphere_colors"] = !attributes.colors.empty();
        nlohmann::ordered_json properties = nlohmann::ordered_json::array();
        for (const SphereProperty& property : attributes.properties) {
            nlohmann::ordered_json entry;
            entry["name"] = property.name;
            if (property.categorical()) entry["labels"] = property.labels;
            properties.push_back(std::move(entry));
        }
        header["sphere_properties"] = std::move(properties);
    }
    header["scene"] = nlohmann::ordered_json::parse(write_scene_json(without_spheres));
    nlohmann::ordered_json animation = detail::animation_to_json(scene.animation);
    if (!animation.is_null()) header["animation"] = std::move(animation);
    return header.dump();
}

}  // namespace

bool has_scene_binary_magic(std::string_view bytes) { return bytes.starts_with(kSceneBinaryMagic); }

std::string write_scene_binary(const Scene& scene) {
    const bool names = any_sphere_named(scene);
    const SphereAttributes& attributes = scene.sphere_attributes;
    // Version 1 for a scene without per-sphere attributes: such files stay
    // the same bytes, readable by an Orb that knows only version 1.
    const std::uint32_t version = attributes.empty() ? 1 : kSceneBinaryVersion;
    const std::string header = header_json(scene, names, version);
    const std::size_t count = scene.spheres.size();

    std::string out;
    out.reserve(detail::kBinaryPreambleSize + header.size() + 8 + count * (names ? 40 : 36));
    out.append(kSceneBinaryMagic);
    detail::append_little_endian<std::uint32_t>(out, version);
    detail::append_little_endian<std::uint32_t>(out, static_cast<std::uint32_t>(header.size()));
    out += header;
    out.append(detail::binary_padding(out.size()), '\0');
    for (const Sphere& s : scene.spheres)
        for (double c : s.center) detail::append_little_endian<double>(out, c);
    for (const Sphere& s : scene.spheres) detail::append_little_endian<double>(out, s.radius);
    for (const Sphere& s : scene.spheres) detail::append_little_endian<std::uint32_t>(out, s.material);
    if (names) {
        for (const Sphere& s : scene.spheres)
            detail::append_little_endian<std::uint32_t>(out, static_cast<std::uint32_t>(s.name.size()));
        for (const Sphere& s : scene.spheres) out += s.name;
    }
    if (!attributes.empty()) {
        out.append(detail::binary_padding(out.size()), '\0');
        for (float c : attributes.colors) detail::append_little_endian<float>(out, c);
        for (const SphereProperty& property : attributes.properties)
            for (float value : property.values) detail::append_little_endian<float>(out, value);
    }
    return out;
}

}  // namespace orb
