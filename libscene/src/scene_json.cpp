// The canonical scene's JSON form: a strict reader that names the JSON path of
// every problem, and a writer whose output is stable and diff-friendly.
#include "orb/scene/scene_json.h"

#include "orb/scene/camera_frame.h"
#include "orb/scene/content_hash.h"

#include <nlohmann/json.hpp>

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "animation_json.h"
#include "float_limits.h"
#include "json_reader.h"
#include "orb/scene/detail/json_text.h"
#include "orb/scene/detail/material_types.h"
#include "orb/scene/error.h"
#include "scene_json_attributes.h"
#include "scene_json_environment.h"
#include "scene_json_spheres.h"

namespace orb {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

using Reader = detail::JsonReader;

Camera read_camera(const Reader& r, const json& value) {
    const std::string path = "camera";
    r.object(value, path);
    r.only_keys(value, path,
                {"position", "target", "up", "vfov_deg", "aperture", "focus_distance", "orthographic_height"});
    Camera camera;
    camera.position = r.numbers<3>(r.member(value, path, "position"), path + ".position");
    camera.target = r.numbers<3>(r.member(value, path, "target"), path + ".target");
    if (value.contains("up")) camera.up = r.numbers<3>(value["up"], path + ".up");
    if (value.contains("vfov_deg")) camera.vfov_deg = r.number(value["vfov_deg"], path + ".vfov_deg");
    if (value.contains("aperture")) camera.aperture = r.number(value["aperture"], path + ".aperture");
    if (value.contains("focus_distance"))
        camera.focus_distance = r.number(value["focus_distance"], path + ".focus_distance");
    if (value.contains("orthographic_height"))
        camera.orthographic_height = r.number(value["orthographic_height"], path + ".orthographic_height");
    return camera;
}

RenderSettings read_render(const Reader& r, const json& value) {
    const std::string path = "render";
    r.object(value, path);
    r.only_keys(value, path, {"width", "height", "spp", "max_depth"});
    RenderSettings render;
    if (value.contains("width")) render.width = static_cast<int>(r.integer(value["width"], "render.width", 1, kMaxImageSide));
    if (value.contains("height"))
        render.height = static_cast<int>(r.integer(value["height"], "render.height", 1, kMaxImageSide));
    if (value.contains("spp")) render.spp = static_cast<int>(r.integer(value["spp"], "render.spp", 1, kMaxSpp));
    if (value.contains("max_depth"))
        render.max_depth = static_cast<int>(r.integer(value["max_depth"], "render.max_depth", 1, kMaxDepth));
    return render;
}

MaterialType read_material_type(const Reader& r, const json& value, const std::string& path) {
    const std::string name = r.string(value, path);
    if (const std::optional<MaterialType> type = detail::material_type_from_name(name)) return *type;
    r.fail(path, "expected " + detail::quoted_material_type_names(nullptr, " or ") + ", got \"" + name + "\"");
}

// glTF's defaults for a metallic-roughness material without factors.
constexpr double kPbrDefaultRoughness = 1.0;
constexpr double kPbrDefaultMetallic = 1.0;

// A number in [0, 1] under `key`, a key that only some material types have.
double read_unit_parameter(const Reader& r, const json& m, const std::string& path, const std::string& key,
                           bool applies, const std::string& type_name, double fallback) {
    if (!m.contains(key)) return fallback;
    const std::string key_path = path + "." + key;
    if (!applies) {
        const std::string owners =
            detail::quoted_material_type_names(key == "roughness" ? has_roughness : has_metallic, " and ") +
            " materials have one";
        r.fail(key_path, "a \"" + type_name + "\" material has no " + key + " (only " + owners +
                             "; a rough metal is \"pbr\" with \"metallic\": 1)");
    }
    const double value = r.number(m[key], key_path);
    if (!(value >= 0.0 && value <= 1.0)) r.fail(key_path, "must be in [0, 1], got " + detail::format_number(value));
    return value;
}

std::vector<Material> read_materials(const Reader& r, const json& value) {
    r.array(value, "materials");
    std::vector<Material> materials;
    materials.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string path = Reader::index("materials", i);
        const json& m = r.object(value[i], path);
        r.only_keys(m, path, {"name", "type", "color", "emission", "ior", "roughness", "metallic"});
        Material material;
        if (m.contains("name")) material.name = r.string(m["name"], path + ".name");
        material.type = read_material_type(r, r.member(m, path, "type"), path + ".type");
        material.color = m.contains("color") ? r.numbers<3>(m["color"], path + ".color") : Vec3{0.8, 0.8, 0.8};
        if (m.contains("emission")) material.emission = r.numbers<3>(m["emission"], path + ".emission");
        if (m.contains("ior")) material.ior = r.number(m["ior"], path + ".ior");
        const std::string type_name = m["type"].get<std::string>();
        const bool pbr = material.type == MaterialType::Pbr;
        material.roughness = read_unit_parameter(r, m, path, "roughness", has_roughness(material.type), type_name,
                                                 pbr ? kPbrDefaultRoughness : 0.0);
        material.metallic = read_unit_parameter(r, m, path, "metallic", has_metallic(material.type), type_name,
                                                pbr ? kPbrDefaultMetallic : 0.0);
        materials.push_back(std::move(material));
    }
    return materials;
}

std::uint32_t resolve_material(const Reader& r, const json& value, const std::string& path,
                               const std::vector<Material>& materials) {
    if (value.is_string()) {
        const std::string name = value.get<std::string>();
        std::optional<std::uint32_t> found;
        for (std::size_t i = 0; i < materials.size(); ++i) {
            if (materials[i].name != name) continue;
            if (found) r.fail(path, "material name \"" + name + "\" is ambiguous (several materials have it)");
            found = static_cast<std::uint32_t>(i);
        }
        if (!found) r.fail(path, "no material is named \"" + name + "\"");
        return *found;
    }
    if (!value.is_number()) r.fail(path, "expected a material index or name");
    const long long count = static_cast<long long>(materials.size());
    if (count == 0) r.fail(path, "refers to a material but \"materials\" is empty");
    return static_cast<std::uint32_t>(r.integer(value, path, 0, count - 1));
}

std::vector<Sphere> read_spheres(const Reader& r, const json& value, const std::vector<Material>& materials) {
    r.array(value, "spheres");
    std::vector<Sphere> spheres;
    spheres.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string path = Reader::index("spheres", i);
        const json& s = r.object(value[i], path);
        r.only_keys(s, path, {"name", "center", "radius", "material"});
        Sphere sphere;
        if (s.contains("name")) sphere.name = r.string(s["name"], path + ".name");
        sphere.center = r.numbers<3>(r.member(s, path, "center"), path + ".center");
        sphere.radius = r.number(r.member(s, path, "radius"), path + ".radius");
        sphere.material = resolve_material(r, r.member(s, path, "material"), path + ".material", materials);
        spheres.push_back(std::move(sphere));
    }
    return spheres;
}

// "line:column" of a byte offset, for JSON syntax errors.
std::string line_and_column(std::string_view text, std::size_t offset) {
    int line = 1, column = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return std::to_string(line) + ":" + std::to_string(column);
}

// "line:column" of the first number literal that does not fit a double.
std::string locate_overflowing_number(std::string_view text) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '"') {  // skip strings
            for (++i; i < text.size() && text[i] != '"'; ++i)
                if (text[i] == '\\') ++i;
            continue;
        }
        if (c != '-' && (c < '0' || c > '9')) continue;
        std::size_t end = i;
        while (end < text.size() && std::string_view("+-0123456789.eE").find(text[end]) != std::string_view::npos) ++end;
        const std::string literal(text.substr(i, end - i));
        if (!std::isfinite(std::strtod(literal.c_str(), nullptr))) return line_and_column(text, i);
        i = end;
    }
    return "1:1";
}

std::string fmt(double d) { return detail::format_number(d); }
std::string fmt(const Vec3& v) {
    std::string text("[");  // appended, not "[" + string: GCC 12 warns falsely (-Wrestrict) on that form
    text += fmt(v[0]);
    text += ", ";
    text += fmt(v[1]);
    text += ", ";
    text += fmt(v[2]);
    text += "]";
    return text;
}

void check(bool ok, const std::string& source, const std::string& path, const std::string& message) {
    if (!ok) throw InputError(source + ": " + path + ": " + message);
}

bool all_finite(const Vec3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

bool within_magnitude(const Vec3& v) {
    return detail::within_magnitude(v[0]) && detail::within_magnitude(v[1]) && detail::within_magnitude(v[2]);
}

void check_coordinates(const Vec3& v, const std::string& source, const std::string& path) {
    check(all_finite(v), source, path, "expected finite numbers");
    check(within_magnitude(v), source, path, detail::magnitude_rule() + detail::kFloatReason + fmt(v));
}

ordered_json vec3_json(const Vec3& v) { return ordered_json::array({v[0], v[1], v[2]}); }

}  // namespace

void validate_scene(const Scene& scene, const std::string& source) {
    const Camera& c = scene.camera;
    check_coordinates(c.position, source, "camera.position");
    check_coordinates(c.target, source, "camera.target");
    check_coordinates(c.up, source, "camera.up");
    const Vec3 forward{c.target[0] - c.position[0], c.target[1] - c.position[1], c.target[2] - c.position[2]};
    // hypot: lengths of huge but finite coordinates must not overflow to infinity.
    const double forward_length = std::hypot(forward[0], forward[1], forward[2]);
    check(forward_length > 0, source, "camera.target", "must differ from camera.position, both are " + fmt(c.position));
    const double up_length = std::hypot(c.up[0], c.up[1], c.up[2]);
    check(up_length > 0, source, "camera.up", "must not be the zero vector");
    check(view_up_sine(forward, c.up) > kMinViewUpSine, source, "camera.up",
          "the view direction (target - position) is parallel to up " + fmt(c.up) + ": the camera's roll is undefined");
    check(std::isfinite(c.vfov_deg) && c.vfov_deg > 0 && c.vfov_deg < 180, source, "camera.vfov_deg",
          "must be in (0, 180), got " + fmt(c.vfov_deg));
    check(std::isfinite(c.aperture) && c.aperture >= 0, source, "camera.aperture", "must be >= 0, got " + fmt(c.aperture));
    check(c.aperture <= kMaxSceneMagnitude, source, "camera.aperture",
          "must be <= " + fmt(kMaxSceneMagnitude) + detail::kFloatReason + fmt(c.aperture));
    check(std::isfinite(c.focus_distance) && c.focus_distance > 0, source, "camera.focus_distance",
          "must be > 0, got " + fmt(c.focus_distance));
    check(detail::positive_in_range(c.focus_distance), source, "camera.focus_distance",
          detail::positive_rule() + detail::kFloatReason + fmt(c.focus_distance));
    // 0 is the perspective camera; an orthographic view's height is a length like a radius.
    check(c.orthographic_height == 0 || detail::positive_in_range(c.orthographic_height), source,
          "camera.orthographic_height",
          "must be 0 (a perspective camera) or in [" + fmt(kMinScenePositive) + ", " + fmt(kMaxSceneMagnitude) +
              "] (an orthographic view that many units high)" + detail::kFloatReason + fmt(c.orthographic_height));

    const RenderSettings& r = scene.render;
    check(r.width >= 1 && r.width <= kMaxImageSide, source, "render.width", "must be in [1, " + std::to_string(kMaxImageSide) + "]");
    check(r.height >= 1 && r.height <= kMaxImageSide, source, "render.height", "must be in [1, " + std::to_string(kMaxImageSide) + "]");
    check(r.spp >= 1 && r.spp <= kMaxSpp, source, "render.spp", "must be in [1, " + std::to_string(kMaxSpp) + "]");
    check(r.max_depth >= 1 && r.max_depth <= kMaxDepth, source, "render.max_depth",
          "must be in [1, " + std::to_string(kMaxDepth) + "]");

    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        const std::string path = "materials[" + std::to_string(i) + "]";
        for (int k = 0; k < 3; ++k) {
            check(std::isfinite(m.color[k]) && m.color[k] >= 0 && m.color[k] <= 1, source, path + ".color",
                  "each component must be in [0, 1], got " + fmt(m.color));
            check(std::isfinite(m.emission[k]) && m.emission[k] >= 0, source, path + ".emission",
                  "each component must be finite and >= 0, got " + fmt(m.emission));
            check(m.emission[k] <= kMaxEmission, source, path + ".emission",
                  "each component must be <= " + fmt(kMaxEmission) + detail::kFloatReason + fmt(m.emission));
        }
        check(std::isfinite(m.ior) && m.ior > 0, source, path + ".ior", "must be > 0, got " + fmt(m.ior));
        const char* type = material_type_name(m.type);
        check(std::isfinite(m.roughness) && m.roughness >= 0 && m.roughness <= 1, source, path + ".roughness",
              "must be in [0, 1], got " + fmt(m.roughness));
        check(has_roughness(m.type) || m.roughness == 0, source, path + ".roughness",
              std::string("a \"") + type + "\" material has no roughness (must be 0), got " + fmt(m.roughness));
        check(std::isfinite(m.metallic) && m.metallic >= 0 && m.metallic <= 1, source, path + ".metallic",
              "must be in [0, 1], got " + fmt(m.metallic));
        check(has_metallic(m.type) || m.metallic == 0, source, path + ".metallic",
              std::string("a \"") + type + "\" material has no metallic (must be 0), got " + fmt(m.metallic));
        check(detail::positive_in_range(m.ior), source, path + ".ior",
              detail::positive_rule() + detail::kFloatReason + fmt(m.ior));
    }
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        // Building the messages below costs more than the checks: skip them for a valid sphere.
        // (The same rules as the checks below, all of them: a valid sphere passes both or neither.)
        if (all_finite(s.center) && within_magnitude(s.center) && std::isfinite(s.radius) && s.radius > 0 &&
            detail::positive_in_range(s.radius) && s.material < scene.materials.size())
            continue;
        const std::string path = "spheres[" + std::to_string(i) + "]";
        check_coordinates(s.center, source, path + ".center");
        check(std::isfinite(s.radius) && s.radius > 0, source, path + ".radius", "must be > 0, got " + fmt(s.radius));
        check(detail::positive_in_range(s.radius), source, path + ".radius",
              detail::positive_rule() + detail::kFloatReason + fmt(s.radius));
        check(s.material < scene.materials.size(), source, path + ".material",
              "index " + std::to_string(s.material) + " is out of range (there are " +
                  std::to_string(scene.materials.size()) + " materials)");
    }
    detail::validate_sphere_attributes(scene.sphere_attributes, scene.spheres.size(), source);
    detail::validate_animation(scene.animation, scene.spheres.size(), source);
    detail::validate_environment(scene.environment, source);
}

Scene load_scene_json(std::string_view text, const std::string& source) {
    json document;
    try {
        document = json::parse(text.begin(), text.end());
    } catch (const json::parse_error& e) {
        // nlohmann's message starts with its own prefix; keep the part after the position.
        std::string what = e.what();
        const auto colon = what.find(": ", what.find("parse error"));
        std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
        throw InputError(source + ":" + line_and_column(text, e.byte == 0 ? 0 : e.byte - 1) + ": invalid JSON: " + detail);
    } catch (const json::out_of_range&) {
        // A number literal too large for a double; nlohmann names it but not where it is.
        throw InputError(source + ":" + locate_overflowing_number(text) + ": a number overflows a double (expected a finite number)");
    }
    const Reader r(source);
    if (!document.is_object()) r.fail("(root)", "expected an object with \"format\": \"orb-scene\"");
    r.only_keys(document, "",
                {"format", "version", "camera", "render", "environment", "materials", "spheres", "sphere_colors",
                 "sphere_properties", "animation"});
    const json& format = r.member(document, "(root)", "format");
    if (!format.is_string() || format.get<std::string>() != "orb-scene")
        r.fail("format", "expected \"orb-scene\", got " + format.dump());
    const long long version = r.integer(r.member(document, "(root)", "version"), "version", 1, 1'000'000);
    if (version > kSceneFormatVersion)
        r.fail("version", "this is a version " + std::to_string(version) + " scene; this Orb reads up to version " +
                              std::to_string(kSceneFormatVersion));

    Scene scene;
    scene.camera = read_camera(r, r.member(document, "(root)", "camera"));
    if (document.contains("render")) scene.render = read_render(r, document["render"]);
    if (document.contains("environment"))
        scene.environment = detail::environment_from_json(r, document["environment"]);
    scene.materials = read_materials(r, r.member(document, "(root)", "materials"));
    scene.spheres = read_spheres(r, r.member(document, "(root)", "spheres"), scene.materials);
    scene.sphere_attributes = detail::sphere_attributes_from_json(
        r, document.contains("sphere_colors") ? &document["sphere_colors"] : nullptr,
        document.contains("sphere_properties") ? &document["sphere_properties"] : nullptr);
    if (document.contains("animation"))
        scene.animation = detail::animation_from_json(document["animation"], "animation", source);
    validate_scene(scene, source);
    return scene;
}

namespace {

// The canonical JSON text of `scene`, handed to `sink` in order: what
// write_scene_json returns and scene_content_hash hashes, without the whole
// text in memory for the hash. Without `with_attributes`, the per-sphere
// arrays are left out (the hash reads their bits instead).
void write_scene_json_to(const Scene& scene, const detail::JsonSink& sink, bool with_attributes) {
    ordered_json document;
    document["format"] = "orb-scene";
    document["version"] = kSceneFormatVersion;

    const Camera& c = scene.camera;
    ordered_json camera;
    camera["position"] = vec3_json(c.position);
    camera["target"] = vec3_json(c.target);
    camera["up"] = vec3_json(c.up);
    camera["vfov_deg"] = c.vfov_deg;
    camera["aperture"] = c.aperture;
    camera["focus_distance"] = c.focus_distance;
    // Written only for an orthographic camera, so a perspective scene is written, and hashed, as before the key existed.
    if (c.orthographic_height != 0) camera["orthographic_height"] = c.orthographic_height;
    document["camera"] = std::move(camera);

    ordered_json render;
    render["width"] = scene.render.width;
    render["height"] = scene.render.height;
    render["spp"] = scene.render.spp;
    render["max_depth"] = scene.render.max_depth;
    document["render"] = std::move(render);
    ordered_json environment = detail::environment_to_json(scene.environment);
    if (!environment.is_null()) document["environment"] = std::move(environment);

    ordered_json materials = ordered_json::array();
    for (const Material& m : scene.materials) {
        ordered_json material;
        material["name"] = m.name;
        material["type"] = material_type_name(m.type);
        material["color"] = vec3_json(m.color);
        material["emission"] = vec3_json(m.emission);
        material["ior"] = m.ior;
        // A smooth dielectric is written without roughness, so scenes without
        // the rough materials are written exactly as before they existed.
        if (m.type == MaterialType::Pbr || (has_roughness(m.type) && m.roughness != 0)) material["roughness"] = m.roughness;
        if (has_metallic(m.type)) material["metallic"] = m.metallic;
        materials.push_back(std::move(material));
    }
    document["materials"] = std::move(materials);

    // The spheres are written directly (scene_json_spheres.h) in place of the
    // empty array that format_json puts last: "  \"spheres\": []\n}".
    document["spheres"] = ordered_json::array();
    const std::string head = detail::format_json(document);
    sink(std::string_view(head).substr(0, head.size() - 4));
    detail::write_spheres_json(scene.spheres, sink);
    if (with_attributes) detail::write_sphere_attributes_json(scene.sphere_attributes, sink);

    ordered_json animation = detail::animation_to_json(scene.animation);
    if (!animation.is_null()) {
        ordered_json wrapper;  // formats as "{\n  \"animation\": ...\n}"
        wrapper["animation"] = std::move(animation);
        const std::string part = detail::format_json(wrapper);
        sink(",\n");
        sink(std::string_view(part).substr(2, part.size() - 4));
    }
    sink("\n}\n");
}

}  // namespace

std::string write_scene_json(const Scene& scene) {
    std::string text;
    text.reserve(4096 + scene.spheres.size() * detail::kSphereLineBytes);
    write_scene_json_to(scene, [&text](std::string_view piece) { text += piece; }, true);
    return text;
}

std::string scene_content_hash(const Scene& scene) {
    ContentHash hash;
    write_scene_json_to(scene, [&hash](std::string_view piece) { hash.add(piece); }, false);
    detail::hash_sphere_attributes(scene.sphere_attributes, hash);
    if (const auto& image = scene.environment.image) {
        hash.add_uint32(static_cast<std::uint32_t>(image->width));
        hash.add_uint32(static_cast<std::uint32_t>(image->height));
        for (float value : image->rgb) hash.add_uint32(std::bit_cast<std::uint32_t>(value));
    }
    return hash.hex();
}

}  // namespace orb
