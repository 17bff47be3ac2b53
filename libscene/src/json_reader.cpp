#include "json_reader.h"

#include <cmath>

#include "orb/scene/error.h"

namespace orb::detail {

void JsonReader::fail(const std::string& path, const std::string& message) const {
    throw InputError(source_ + ": " + path + ": " + message);
}

const JsonReader::json& JsonReader::member(const json& object, const std::string& path, const char* key) const {
    auto it = object.find(key);
    if (it == object.end()) fail(path, std::string("missing required key \"") + key + "\"");
    return *it;
}

void JsonReader::only_keys(const json& object, const std::string& path,
                           std::initializer_list<const char*> allowed) const {
    for (auto it = object.begin(); it != object.end(); ++it) {
        bool known = false;
        for (const char* key : allowed) known = known || it.key() == key;
        if (known) continue;
        std::string list;
        for (const char* key : allowed) list += std::string(list.empty() ? "" : ", ") + key;
        fail(join(path, it.key()), "unknown key (expected one of: " + list + ")");
    }
}

const JsonReader::json& JsonReader::object(const json& value, const std::string& path) const {
    if (!value.is_object()) fail(path, "expected an object, got " + describe(value));
    return value;
}

const JsonReader::json& JsonReader::array(const json& value, const std::string& path) const {
    if (!value.is_array()) fail(path, "expected an array, got " + describe(value));
    return value;
}

double JsonReader::number(const json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, "expected a number, got " + describe(value));
    const double d = value.get<double>();
    if (!std::isfinite(d)) fail(path, "expected a finite number");
    return d;
}

std::int64_t JsonReader::integer(const json& value, const std::string& path, std::int64_t lo, std::int64_t hi) const {
    const bool whole = value.is_number_integer() ||
                       (value.is_number_float() && std::isfinite(value.get<double>()) &&
                        std::floor(value.get<double>()) == value.get<double>());
    if (!whole) fail(path, "expected an integer, got " + describe(value));
    const double d = value.get<double>();
    if (d < static_cast<double>(lo) || d > static_cast<double>(hi))
        fail(path, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + value.dump());
    return static_cast<std::int64_t>(d);
}

std::string JsonReader::string(const json& value, const std::string& path) const {
    if (!value.is_string()) fail(path, "expected a string, got " + describe(value));
    return value.get<std::string>();
}

std::string JsonReader::describe(const json& value) {
    std::string text = value.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return std::string(value.type_name()) + " " + text;
}

}  // namespace orb::detail
