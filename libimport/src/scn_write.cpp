// Writes a scene in SmallptGPU's .scn form and lists what that form cannot
// hold (docs/scn-format.md, "What --to scn loses").
#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "orb/import/scn.h"

namespace orb {
namespace {

// Shortest text that reads back to the same double, in plain decimals when
// that stays short ("100000" rather than "1e+05"); both forms are strtod syntax.
void append_number(std::string& out, double value) {
    char shortest[64];
    char fixed[64];
    const auto s = std::to_chars(shortest, shortest + sizeof shortest, value);
    const std::string_view shortest_text(shortest, static_cast<size_t>(s.ptr - shortest));
    if (shortest_text.find('e') != std::string_view::npos) {
        const auto f = std::to_chars(fixed, fixed + sizeof fixed, value, std::chars_format::fixed);
        if (f.ec == std::errc() && f.ptr - fixed <= 24) {
            out.append(fixed, f.ptr);
            return;
        }
    }
    out += shortest_text;
}

void append_numbers(std::string& out, const Vec3& v) {
    for (double x : v) {
        out += ' ';
        append_number(out, x);
    }
}

std::string format_number(double value) {
    std::string out;
    append_number(out, value);
    return out;
}

// A pbr material becomes the .scn kind it is closest to: a mirror when mostly metal, else diffuse.
constexpr double kScnMetalThreshold = 0.5;

// SmallptGPU's material codes (docs/scn-format.md): the kinds .scn has. Any
// other kind has none (the default, so a kind added to ORB_MATERIAL_TABLE is
// written as diffuse and named as a loss, never silently).
std::optional<int> exact_material_code(MaterialType type) {
    switch (type) {
        case MaterialType::Diffuse: return 0;
        case MaterialType::Mirror: return 1;
        case MaterialType::Dielectric: return 2;
        default: return std::nullopt;
    }
}

int material_code(const Material& material) {
    if (const std::optional<int> code = exact_material_code(material.type)) return *code;
    return material.type == MaterialType::Pbr && material.metallic >= kScnMetalThreshold ? 1 : 0;
}

// SmallptGPU's glass has this index of refraction, its camera this field of view.
constexpr double kScnGlassIor = 1.5;
// Below this, a field of view differs from SmallptGPU's by less than a tenth of a pixel at 640x480.
constexpr double kFovToleranceDeg = 0.01;

void list_camera_losses(const Camera& camera, std::vector<std::string>& lossy) {
    const Vec3& up = camera.up;
    if (!(up[0] == 0.0 && up[2] == 0.0 && up[1] > 0.0))
        lossy.push_back("camera up vector [" + format_number(up[0]) + ", " + format_number(up[1]) + ", " +
                        format_number(up[2]) + "] is not +y; .scn cameras always have +y up");
    // An orthographic camera's field of view does not apply, so only its projection is named.
    if (camera.orthographic_height > 0)
        lossy.push_back("camera is orthographic (a view " + format_number(camera.orthographic_height) +
                        " units high); .scn cameras are perspective, so it is written as SmallptGPU's perspective camera");
    else if (!(std::fabs(camera.vfov_deg - smallptgpu_vfov_deg()) <= kFovToleranceDeg))
        lossy.push_back("camera vfov_deg " + format_number(camera.vfov_deg) + " is not SmallptGPU's fixed " +
                        format_number(smallptgpu_vfov_deg()) + "; .scn has no field of view");
    if (camera.aperture != 0.0)
        lossy.push_back("camera aperture " + format_number(camera.aperture) +
                        " (depth of field) is dropped; .scn cameras are pinholes");
}

void list_render_losses(const RenderSettings& render, std::vector<std::string>& lossy) {
    const RenderSettings defaults;
    std::string changed;
    const auto note = [&](const char* key, int value, int default_value) {
        if (value == default_value) return;
        changed += (changed.empty() ? "" : ", ") + std::string(key) + " " + std::to_string(value);
    };
    note("width", render.width, defaults.width);
    note("height", render.height, defaults.height);
    note("spp", render.spp, defaults.spp);
    note("max_depth", render.max_depth, defaults.max_depth);
    if (!changed.empty()) lossy.push_back("render settings (" + changed + ") are not stored in .scn");
}

void list_material_losses(const std::vector<Material>& materials, std::vector<std::string>& lossy) {
    for (size_t i = 0; i < materials.size(); ++i) {
        const Material& m = materials[i];
        const std::string which = "material " + std::to_string(i) + " ('" + m.name + "')";
        if (m.type == MaterialType::Dielectric && m.ior != kScnGlassIor)
            lossy.push_back(which + " is a dielectric with ior " + format_number(m.ior) +
                            "; .scn glass always has ior 1.5");
        if (m.type == MaterialType::Dielectric && m.roughness != 0.0)
            lossy.push_back(which + " is rough glass (roughness " + format_number(m.roughness) +
                            "); .scn glass is smooth");
        if (m.type == MaterialType::Pbr)
            lossy.push_back(which + " is pbr (metallic " + format_number(m.metallic) + ", roughness " +
                            format_number(m.roughness) + "); .scn has no such material: written as " +
                            (m.metallic >= kScnMetalThreshold ? "a mirror" : "diffuse"));
        else if (!exact_material_code(m.type))
            lossy.push_back(which + " is " + material_type_name(m.type) +
                            "; .scn has no such material: written as diffuse");
    }
}

}  // namespace

ScnWriteResult write_scn(const Scene& scene) {
    ScnWriteResult result;
    list_camera_losses(scene.camera, result.lossy);
    list_render_losses(scene.render, result.lossy);
    list_material_losses(scene.materials, result.lossy);
    if (!scene.animation.empty()) result.lossy.push_back("the animation is dropped; .scn scenes are static");
    if (!scene.sphere_attributes.properties.empty())
        result.lossy.push_back("the " + std::to_string(scene.sphere_attributes.properties.size()) +
                               " sphere properties are dropped; .scn has none (their colours and radii, once applied "
                               "with --color-by or --radius-by, are kept)");
    if (scene.environment.kind != EnvironmentKind::None)
        result.lossy.push_back("the environment light is dropped; SmallptGPU has none (rays that leave a .scn scene "
                               "see black), so the scene will render darker");

    std::string& out = result.text;
    out.reserve(64 + 96 * scene.spheres.size());
    out += "camera";
    append_numbers(out, scene.camera.position);
    out += ' ';
    append_numbers(out, scene.camera.target);
    out += "\nsize " + std::to_string(scene.spheres.size()) + "\n";
    for (size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& sphere = scene.spheres[i];
        if (sphere.material >= scene.materials.size())
            throw std::invalid_argument("write_scn: sphere " + std::to_string(i) + " refers to material " +
                                        std::to_string(sphere.material) + ", which does not exist");
        const Material& material = scene.materials[sphere.material];
        out += "sphere ";
        append_number(out, sphere.radius);
        out += ' ';
        append_numbers(out, sphere.center);
        out += ' ';
        append_numbers(out, material.emission);
        out += ' ';
        // .scn gives every sphere its own colour: a per-sphere colour is kept exactly.
        const std::vector<float>& colors = scene.sphere_attributes.colors;
        const bool own_color = colors.size() == 3 * scene.spheres.size();  // validate_scene's rule
        append_numbers(out, own_color ? Vec3{colors[3 * i], colors[3 * i + 1], colors[3 * i + 2]} : material.color);
        out += "  " + std::to_string(material_code(material)) + "\n";
    }
    return result;
}

}  // namespace orb
