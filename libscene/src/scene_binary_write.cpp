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
std::string header_json(const Scene& scene, bool names) {
    Scene without_spheres;
    without_spheres.camera = scene.camera;
    without_spheres.render = scene.render;
    without_spheres.environment = scene.environment;
    without_spheres.materials = scene.materials;
    nlohmann::ordered_json header;
    header["format"] = "orb-scene-binary";
    header["version"] = kSceneBinaryVersion;
    header["sphere_count"] = scene.spheres.size();
    header["sphere_names"] = names;
    header["scene"] = nlohmann::ordered_json::parse(write_scene_json(without_spheres));
    nlohmann::ordered_json animation = detail::animation_to_json(scene.animation);
    if (!animation.is_null()) header["animation"] = std::move(animation);
    return header.dump();
}

}  // namespace

bool has_scene_binary_magic(std::string_view bytes) { return bytes.starts_with(kSceneBinaryMagic); }

std::string write_scene_binary(const Scene& scene) {
    const bool names = any_sphere_named(scene);
    const std::string header = header_json(scene, names);
    const std::size_t count = scene.spheres.size();

    std::string out;
    out.reserve(detail::kBinaryPreambleSize + header.size() + 8 + count * (names ? 40 : 36));
    out.append(kSceneBinaryMagic);
    detail::append_little_endian<std::uint32_t>(out, kSceneBinaryVersion);
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
    return out;
}

}  // namespace orb
