#include "scene_json_attributes.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <set>

#include "orb/scene/detail/json_text.h"
#include "orb/scene/error.h"

namespace orb::detail {
namespace {

using json = nlohmann::json;

// Shortest text that reads back as the same float: the arrays hold floats,
// and "0.8" is what a reader wrote, not "0.800000011920929".
void append_float(std::string& out, float value) {
    if (!std::isfinite(value)) {  // a property's "no value" (NaN); validation refuses the rest: never invalid JSON
        out += "null";
        return;
    }
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

float read_float(const JsonReader& r, const json& value, const std::string& path) {
    const double number = r.number(value, path);
    const float narrowed = static_cast<float>(number);
    if (!std::isfinite(narrowed)) r.fail(path, "does not fit a 32-bit float, got " + format_number(number));
    return narrowed;
}

std::string describe_color(const float* rgb) {
    std::string text("[");  // appended, not "[" + string: GCC 12 warns falsely (-Wrestrict) on that form
    for (int c = 0; c < 3; ++c) {
        if (c) text += ", ";
        append_float(text, rgb[c]);
    }
    text += "]";
    return text;
}

[[noreturn]] void fail(const std::string& source, const std::string& path, const std::string& message) {
    throw InputError(source + ": " + path + ": " + message);
}

}  // namespace

SphereAttributes sphere_attributes_from_json(const JsonReader& r, const json* colors, const json* properties) {
    SphereAttributes attributes;
    if (colors) {
        r.array(*colors, "sphere_colors");
        attributes.colors.reserve(colors->size() * 3);
        for (std::size_t i = 0; i < colors->size(); ++i) {
            const std::string path = JsonReader::index("sphere_colors", i);
            const json& rgb = (*colors)[i];
            if (!rgb.is_array() || rgb.size() != 3)
                r.fail(path, "expected an array of 3 numbers, got " + JsonReader::describe(rgb));
            for (std::size_t c = 0; c < 3; ++c) attributes.colors.push_back(read_float(r, rgb[c], JsonReader::index(path, c)));
        }
    }
    if (properties) {
        r.array(*properties, "sphere_properties");
        for (std::size_t p = 0; p < properties->size(); ++p) {
            const std::string path = JsonReader::index("sphere_properties", p);
            const json& object = r.object((*properties)[p], path);
            r.only_keys(object, path, {"name", "labels", "values"});
            SphereProperty property;
            property.name = r.string(r.member(object, path, "name"), path + ".name");
            if (object.contains("labels")) {
                const json& labels = r.array(object["labels"], path + ".labels");
                if (labels.empty()) r.fail(path + ".labels", "must not be empty (leave it out for a numeric property)");
                for (std::size_t k = 0; k < labels.size(); ++k)
                    property.labels.push_back(r.string(labels[k], JsonReader::index(path + ".labels", k)));
            }
            const json& values = r.array(r.member(object, path, "values"), path + ".values");
            property.values.reserve(values.size());
            for (std::size_t i = 0; i < values.size(); ++i)  // null: the sphere has no value
                property.values.push_back(values[i].is_null()
                                              ? kNoValue
                                              : read_float(r, values[i], JsonReader::index(path + ".values", i)));
            attributes.properties.push_back(std::move(property));
        }
    }
    return attributes;
}

void write_sphere_attributes_json(const SphereAttributes& attributes, const JsonSink& sink) {
    if (!attributes.colors.empty()) {
        // One sphere's colour per line, like the spheres, in pieces of 16384.
        constexpr std::size_t kPerPiece = 16384;
        const std::size_t count = attributes.colors.size() / 3;
        sink(",\n  \"sphere_colors\": [\n");
        std::string piece;
        for (std::size_t i = 0; i < count; ++i) {
            piece += "    [";
            append_float(piece, attributes.colors[3 * i]);
            piece += ", ";
            append_float(piece, attributes.colors[3 * i + 1]);
            piece += ", ";
            append_float(piece, attributes.colors[3 * i + 2]);
            piece += i + 1 < count ? "],\n" : "]\n";
            if ((i + 1) % kPerPiece == 0) {
                sink(piece);
                piece.clear();
            }
        }
        piece += "  ]";
        sink(piece);
    }
    if (!attributes.properties.empty()) {
        sink(",\n  \"sphere_properties\": [\n");
        for (std::size_t p = 0; p < attributes.properties.size(); ++p) {
            const SphereProperty& property = attributes.properties[p];
            std::string text = "    { \"name\": " + nlohmann::ordered_json(property.name).dump();
            if (property.categorical()) {
                text += ", \"labels\": [";
                for (std::size_t k = 0; k < property.labels.size(); ++k) {
                    if (k) text += ", ";
                    text += nlohmann::ordered_json(property.labels[k]).dump();
                }
                text += "]";
            }
            text += ", \"values\": [";
            for (std::size_t i = 0; i < property.values.size(); ++i) {
                if (i) text += ", ";
                append_float(text, property.values[i]);
            }
            text += p + 1 < attributes.properties.size() ? "] },\n" : "] }\n";
            sink(text);
        }
        sink("  ]");
    }
}

void validate_sphere_attributes(const SphereAttributes& attributes, std::size_t sphere_count,
                                const std::string& source) {
    const std::vector<float>& colors = attributes.colors;
    if (!colors.empty()) {
        if (colors.size() != 3 * sphere_count)
            fail(source, "sphere_colors",
                 colors.size() % 3 != 0
                     ? "holds " + std::to_string(colors.size()) + " numbers, not three per sphere"
                     : "has " + std::to_string(colors.size() / 3) + " colours, the scene has " +
                           std::to_string(sphere_count) + " spheres (one colour per sphere, or none)");
        for (std::size_t i = 0; i < colors.size(); ++i) {
            if (colors[i] >= 0.0f && colors[i] <= 1.0f) continue;  // also false for NaN
            const std::size_t sphere = i / 3;
            fail(source, "sphere_colors[" + std::to_string(sphere) + "]",
                 "each component must be in [0, 1], got " + describe_color(&colors[3 * sphere]));
        }
    }
    std::set<std::string> names;
    for (std::size_t p = 0; p < attributes.properties.size(); ++p) {
        const SphereProperty& property = attributes.properties[p];
        const std::string path = "sphere_properties[" + std::to_string(p) + "]";
        if (property.name.empty()) fail(source, path + ".name", "must not be empty");
        if (!names.insert(property.name).second)
            fail(source, path + ".name", "\"" + property.name + "\" names an earlier property too");
        if (property.values.size() != sphere_count)
            fail(source, path + ".values",
                 "has " + std::to_string(property.values.size()) + " values, the scene has " +
                     std::to_string(sphere_count) + " spheres (one value per sphere)");
        const double categories = static_cast<double>(property.labels.size());
        for (std::size_t i = 0; i < property.values.size(); ++i) {
            const float value = property.values[i];
            const std::string where = path + ".values[" + std::to_string(i) + "]";
            if (!has_value(value)) continue;
            if (!std::isfinite(value)) fail(source, where, "expected a finite number (or null: no value)");
            if (property.categorical() && !(value >= 0 && value < categories && value == std::floor(value)))
                {
                std::string got;
                append_float(got, value);
                fail(source, where,
                     "expected an index into the " + std::to_string(property.labels.size()) +
                         " labels (a whole number in [0, " + std::to_string(property.labels.size() - 1) + "]), got " + got);
            }
        }
    }
}

void hash_sphere_attributes(const SphereAttributes& attributes, ContentHash& hash) {
    if (attributes.empty()) return;
    hash.add("sphere_attributes");
    hash.add_uint32(static_cast<std::uint32_t>(attributes.colors.size()));
    for (float value : attributes.colors) hash.add_uint32(std::bit_cast<std::uint32_t>(value));
    hash.add_uint32(static_cast<std::uint32_t>(attributes.properties.size()));
    for (const SphereProperty& property : attributes.properties) {
        hash.add_uint32(static_cast<std::uint32_t>(property.name.size()));
        hash.add(property.name);
        hash.add_uint32(static_cast<std::uint32_t>(property.labels.size()));
        for (const std::string& label : property.labels) {
            hash.add_uint32(static_cast<std::uint32_t>(label.size()));
            hash.add(label);
        }
        hash.add_uint32(static_cast<std::uint32_t>(property.values.size()));
        // Every NaN is the one "no value": a binary scene may hold another NaN's bits.
        for (float value : property.values) hash.add_uint32(std::bit_cast<std::uint32_t>(has_value(value) ? value : kNoValue));
    }
}

}  // namespace orb::detail
