// Reads the binary scene: checks the container (magic, version, sizes) with
// its own messages, then hands the assembled scene to validate_scene, the
// same rules and messages as the JSON form.
#include <nlohmann/json.hpp>

#include <limits>

#include "animation_json.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"
#include "scene_binary_layout.h"

namespace orb {
namespace {

using json = nlohmann::json;

[[noreturn]] void fail(const std::string& source, const std::string& message) {
    throw InputError(source + ": " + message);
}

// The JSON form keeps names as JSON strings, which must be UTF-8; the binary
// form must not let through a name the JSON writer could not write.
bool is_valid_utf8(std::string_view text) {
    std::size_t i = 0;
    while (i < text.size()) {
        const auto byte = static_cast<unsigned char>(text[i]);
        std::size_t length = byte < 0x80 ? 1 : (byte >> 5) == 0x6 ? 2 : (byte >> 4) == 0xE ? 3 : (byte >> 3) == 0x1E ? 4 : 0;
        if (length == 0 || i + length > text.size()) return false;
        std::uint32_t code = length == 1 ? byte : byte & (0x7F >> length);
        for (std::size_t k = 1; k < length; ++k) {
            const auto next = static_cast<unsigned char>(text[i + k]);
            if ((next & 0xC0) != 0x80) return false;
            code = (code << 6) | (next & 0x3F);
        }
        const std::uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
        if (code < smallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return false;
        i += length;
    }
    return true;
}

struct BinaryHeader {
    std::uint64_t sphere_count = 0;
    bool sphere_names = false;
    bool sphere_colors = false;
    Scene scene;  // no spheres yet; sphere_attributes.properties named, without values
};

// Version 2's "sphere_colors" and "sphere_properties": which attribute arrays follow the names.
void read_attribute_keys(const json& header, const std::string& source, BinaryHeader& result) {
    const json colors = header.value("sphere_colors", json());
    if (!colors.is_boolean()) fail(source, "header: sphere_colors: expected true or false");
    result.sphere_colors = colors.get<bool>();
    const json properties = header.value("sphere_properties", json());
    if (!properties.is_array()) fail(source, "header: sphere_properties: expected an array");
    for (std::size_t p = 0; p < properties.size(); ++p) {
        const std::string path = "header: sphere_properties[" + std::to_string(p) + "]";
        const json& entry = properties[p];
        if (!entry.is_object()) fail(source, path + ": expected an object");
        for (const auto& [key, value] : entry.items())
            if (key != "name" && key != "labels") fail(source, path + ": unknown key \"" + key + "\"");
        SphereProperty property;
        if (!entry.contains("name") || !entry["name"].is_string()) fail(source, path + ".name: expected a string");
        property.name = entry["name"].get<std::string>();
        if (entry.contains("labels")) {
            const json& labels = entry["labels"];
            if (!labels.is_array() || labels.empty()) fail(source, path + ".labels: expected a non-empty array of strings");
            for (const json& label : labels) {
                if (!label.is_string()) fail(source, path + ".labels: expected a non-empty array of strings");
                property.labels.push_back(label.get<std::string>());
            }
        }
        result.scene.sphere_attributes.properties.push_back(std::move(property));
    }
}

BinaryHeader read_header(std::string_view text, std::uint32_t version, const std::string& source) {
    const json header = json::parse(text.begin(), text.end(), nullptr, false);
    if (header.is_discarded() || !header.is_object()) fail(source, "header: expected a JSON object (the file is corrupt)");
    for (const auto& [key, value] : header.items())
        if (key != "format" && key != "version" && key != "sphere_count" && key != "sphere_names" && key != "scene" &&
            key != "animation" && !(version >= 2 && (key == "sphere_colors" || key == "sphere_properties")))
            fail(source, "header: unknown key \"" + key + "\"" +
                             (version < 2 && key.starts_with("sphere_") ? " (a version 2 key in a version 1 file)" : ""));
    if (header.value("format", json()) != "orb-scene-binary")
        fail(source, "header: format: expected \"orb-scene-binary\"");
    if (header.value("version", json()) != version)
        fail(source, "header: version: must repeat the container version " + std::to_string(version));
    const json count = header.value("sphere_count", json());
    if (!count.is_number_unsigned()) fail(source, "header: sphere_count: expected a non-negative integer");
    const json names = header.value("sphere_names", json());
    if (!names.is_boolean()) fail(source, "header: sphere_names: expected true or false");
    if (!header.contains("scene")) fail(source, "header: scene: missing");

    BinaryHeader result;
    result.sphere_count = count.get<std::uint64_t>();
    result.sphere_names = names.get<bool>();
    if (version >= 2) read_attribute_keys(header, source, result);
    // The scene part is the JSON form without spheres: the JSON reader checks it.
    SphereAttributes attributes = std::move(result.scene.sphere_attributes);
    result.scene = load_scene_json(header["scene"].dump(), source);
    if (!result.scene.spheres.empty() || !result.scene.animation.empty() || !result.scene.sphere_attributes.empty())
        fail(source,
             "header: scene: spheres, their attributes and animation belong in the arrays and the \"animation\" key");
    result.scene.sphere_attributes = std::move(attributes);
    if (header.contains("animation"))
        result.scene.animation = detail::animation_from_json(header["animation"], "animation", source);
    return result;
}

}  // namespace

Scene load_scene_binary(std::string_view bytes, const std::string& source) {
    if (!has_scene_binary_magic(bytes)) fail(source, "not an Orb binary scene (the file does not start with its magic bytes)");
    if (bytes.size() < detail::kBinaryPreambleSize) fail(source, "truncated: the file ends inside the binary preamble");
    const auto version = detail::from_little_endian<std::uint32_t>(bytes.data() + 8);
    if (version == 0 || version > kSceneBinaryVersion)
        fail(source, "this is a version " + std::to_string(version) + " binary scene; this Orb reads up to version " +
                         std::to_string(kSceneBinaryVersion));
    const auto header_size = detail::from_little_endian<std::uint32_t>(bytes.data() + 12);
    if (header_size > bytes.size() - detail::kBinaryPreambleSize)
        fail(source, "truncated: the header says it is " + std::to_string(header_size) + " bytes, the file has " +
                         std::to_string(bytes.size() - detail::kBinaryPreambleSize) + " after the preamble");
    BinaryHeader header = read_header(bytes.substr(detail::kBinaryPreambleSize, header_size), version, source);

    std::size_t offset = detail::kBinaryPreambleSize + header_size;
    offset += detail::binary_padding(offset);
    const std::uint64_t available = bytes.size() > offset ? bytes.size() - offset : 0;
    const std::uint64_t per_sphere = 8 * 3 + 8 + 4 + (header.sphere_names ? 4 : 0);
    const std::uint64_t n = header.sphere_count;
    if (n > available / per_sphere)
        fail(source, "truncated: the header says " + std::to_string(n) + " spheres (" + std::to_string(per_sphere) +
                         " bytes each), but only " + std::to_string(available) + " bytes follow it");

    Scene scene = std::move(header.scene);
    scene.spheres.resize(static_cast<std::size_t>(n));
    const char* centers = bytes.data() + offset;
    const char* radii = centers + 24 * n;
    const char* materials = radii + 8 * n;
    for (std::size_t i = 0; i < n; ++i) {
        Sphere& s = scene.spheres[i];
        for (int c = 0; c < 3; ++c) s.center[c] = detail::from_little_endian<double>(centers + 24 * i + 8 * c);
        s.radius = detail::from_little_endian<double>(radii + 8 * i);
        s.material = detail::from_little_endian<std::uint32_t>(materials + 4 * i);
    }
    std::size_t end = offset + 36 * n;
    if (header.sphere_names) {
        const char* lengths = bytes.data() + end;
        end += 4 * n;
        for (std::size_t i = 0; i < n; ++i) {
            const auto length = detail::from_little_endian<std::uint32_t>(lengths + 4 * i);
            if (length > bytes.size() - end)
                fail(source, "truncated: spheres[" + std::to_string(i) + "].name runs past the end of the file");
            std::string_view name = bytes.substr(end, length);
            if (!is_valid_utf8(name)) fail(source, "spheres[" + std::to_string(i) + "].name: not valid UTF-8");
            scene.spheres[i].name = std::string(name);
            end += length;
        }
    }
    SphereAttributes& attributes = scene.sphere_attributes;
    const std::uint64_t attribute_floats = (header.sphere_colors ? 3 : 0) + attributes.properties.size();
    if (attribute_floats > 0) {
        end += detail::binary_padding(end);
        const std::uint64_t left = bytes.size() > end ? bytes.size() - end : 0;
        if (n > 0 && attribute_floats > left / 4 / n)
            fail(source, "truncated: the header says " + std::to_string(n) + " spheres with " +
                             std::to_string(attribute_floats) + " attribute floats each, but only " +
                             std::to_string(left) + " bytes follow the sphere arrays");
        auto read_floats = [&](std::vector<float>& into, std::size_t count) {
            into.resize(count);
            for (std::size_t i = 0; i < count; ++i) into[i] = detail::from_little_endian<float>(bytes.data() + end + 4 * i);
            end += 4 * count;
        };
        if (header.sphere_colors) read_floats(attributes.colors, 3 * n);
        for (SphereProperty& property : attributes.properties) read_floats(property.values, n);
    }
    if (end != bytes.size())
        fail(source, std::to_string(bytes.size() - end) + " bytes after the end of the sphere arrays (the file is corrupt)");
    validate_scene(scene, source);
    return scene;
}

}  // namespace orb
