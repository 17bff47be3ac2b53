#include "orb/scene/detail/json_text.h"

#include <charconv>
#include <cmath>

namespace orb::detail {
namespace {

using ordered_json = nlohmann::ordered_json;

std::string scalar(const ordered_json& value) {
    if (value.is_number_float()) return format_number(value.get<double>());
    return value.dump();
}

std::string one_line(const ordered_json& value) {
    if (value.is_object()) {
        if (value.empty()) return "{}";
        std::string out = "{ ";
        bool first = true;
        for (auto it = value.begin(); it != value.end(); ++it) {
            if (!first) out += ", ";
            first = false;
            out += ordered_json(it.key()).dump() + ": " + one_line(it.value());
        }
        return out + " }";
    }
    if (value.is_array()) {
        std::string out = "[";
        for (std::size_t i = 0; i < value.size(); ++i) out += (i ? ", " : "") + one_line(value[i]);
        return out + "]";
    }
    return scalar(value);
}

bool holds_only_scalars(const ordered_json& value) {
    for (const auto& element : value)
        if (element.is_structured()) return false;
    return true;
}

// An object whose members are scalars or arrays of scalars reads best on one line.
bool is_flat(const ordered_json& value) {
    if (value.is_array()) return holds_only_scalars(value);
    if (!value.is_object()) return true;
    for (const auto& member : value)
        if (member.is_object() || (member.is_array() && !holds_only_scalars(member))) return false;
    return true;
}

void format(const ordered_json& value, int depth, std::string& out) {
    if (!value.is_structured() || value.empty() || (depth > 0 && is_flat(value))) {
        out += one_line(value);
        return;
    }
    const std::string indent(2 * (depth + 1), ' ');
    const bool is_object = value.is_object();
    out += is_object ? "{\n" : "[\n";
    std::size_t i = 0;
    for (auto it = value.begin(); it != value.end(); ++it, ++i) {
        out += indent;
        if (is_object) out += ordered_json(it.key()).dump() + ": ";
        format(it.value(), depth + 1, out);
        out += i + 1 < value.size() ? ",\n" : "\n";
    }
    out += std::string(2 * depth, ' ') + (is_object ? "}" : "]");
}

}  // namespace

void append_number(std::string& out, double value) {
    // "-0" would read back as the integer 0; keep the sign of a negative zero.
    if (value == 0.0 && std::signbit(value)) {
        out += "-0.0";
        return;
    }
    char buffer[400];
    const double magnitude = std::fabs(value);
    const bool plain = magnitude == 0.0 || (magnitude >= 1e-5 && magnitude < 1e16);
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value,
                                      plain ? std::chars_format::fixed : std::chars_format::scientific);
    out.append(buffer, result.ptr);
}

std::string format_number(double value) {
    std::string out;
    append_number(out, value);
    return out;
}

std::string format_json(const ordered_json& value) {
    std::string out;
    format(value, 0, out);
    return out;
}

}  // namespace orb::detail
