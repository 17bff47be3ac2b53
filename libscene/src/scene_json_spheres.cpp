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

void write_spheres_json(const std::vector<Sphere>& spheres, const JsonSink& sink) {
    if (spheres.empty()) {
        sink("[]");
        return;
    }
    // About 1.5 MB of text per piece: large enough that the sink's calls cost
    // nothing, small enough to stay in the cache while it reads them.
    constexpr std::size_t kSpheresPerPiece = 16384;
    std::string out = "[\n";
    out.reserve(kSpheresPerPiece * 120);
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        const Sphere& s = spheres[i];
        out += "    { \"name\": ";
        append_name(out, s.name);
        out += ", \"center\": [";
        append_number(out, s.center[0]);
        out += ", ";
        append_number(out, s.center[1]);
        out += ", ";
        append_number(out, s.center[2]);
        out += "], \"radius\": ";
        append_number(out, s.radius);
        out += ", \"material\": ";
        out += std::to_string(s.material);
        out += i + 1 < spheres.size() ? " },\n" : " }\n";
        if ((i + 1) % kSpheresPerPiece == 0) {
            sink(out);
            out.clear();
        }
    }
    out += "  ]";
    sink(out);
}

}  // namespace orb::detail
