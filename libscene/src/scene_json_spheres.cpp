#include "scene_json_spheres.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <future>

#include "orb/scene/detail/json_text.h"

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

// Spheres [first, last) as lines of the array, each with its separator.
std::string format_sphere_lines(const std::vector<Sphere>& spheres, std::size_t first, std::size_t last) {
    std::string out;
    out.reserve((last - first) * kSphereLineBytes);
    for (std::size_t i = first; i < last; ++i) {
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
    }
    return out;
}

}  // namespace

void write_spheres_json(const std::vector<Sphere>& spheres, const JsonSink& sink) {
    if (spheres.empty()) {
        sink("[]");
        return;
    }
    // About 2 MB of text per piece: large enough that the sink's calls and a
    // thread per piece cost nothing, small enough to stay in the cache.
    constexpr std::size_t kSpheresPerPiece = 16384;
    const std::size_t count = spheres.size();
    sink("[\n");
    if (count <= kSpheresPerPiece) {
        sink(format_sphere_lines(spheres, 0, count));
    } else {
        // The next piece is formatted on a second thread while the sink reads
        // this one: formatting and hashing 10 M spheres take about as long
        // as each other (docs/performance.md, "Big scenes").
        auto piece_from = [&spheres, count](std::size_t first) {
            return format_sphere_lines(spheres, first, std::min(first + kSpheresPerPiece, count));
        };
        std::future<std::string> next = std::async(std::launch::async, piece_from, std::size_t{0});
        for (std::size_t first = 0; first < count; first += kSpheresPerPiece) {
            const std::string piece = next.get();
            if (first + kSpheresPerPiece < count)
                next = std::async(std::launch::async, piece_from, first + kSpheresPerPiece);
            sink(piece);
        }
    }
    sink("  ]");
}

}  // namespace orb::detail
