#include "scene_json_spheres.h"

#include <nlohmann/json.hpp>

#include "json_text.h"

namespace orb::detail {
namespace {

// Names that need no escaping are copied; the rest go through nlohmann, as
// the generic writer does (which also refuses invalid UTF-8 the same way).
void append_name(std::string& out, const std::string& name) {
    bool plain = true;
    for (unsigned char c : name) plain = plain && c >= 0x20 && c < 0x7f && c != '"' && c != '\\';
    if (plain) {
        out += '"';
        out += name;
        out += '"';
    } else {
        out += nlohmann::ordered_json(name).dump();
    }
}

}  // namespace

std::string format_spheres_json(const std::vector<Sphere>& spheres) {
    if (spheres.empty()) return "[]";
    std::string out = "[\n";
    out.reserve(spheres.size() * 110);
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        const Sphere& s = spheres[i];
        out += "    { \"name\": ";
        append_name(out, s.name);
        out += ", \"center\": [";
        out += format_number(s.center[0]);
        out += ", ";
        out += format_number(s.center[1]);
        out += ", ";
        out += format_number(s.center[2]);
        out += "], \"radius\": ";
        out += format_number(s.radius);
        out += ", \"material\": ";
        out += std::to_string(s.material);
        out += i + 1 < spheres.size() ? " },\n" : " }\n";
    }
    out += "  ]";
    return out;
}

}  // namespace orb::detail
