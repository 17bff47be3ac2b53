#include "ply_skipped.h"

#include <algorithm>
#include <cctype>
#include <optional>

namespace orb::ply {
namespace {

struct Numbered {
    std::string stem;  // "f_rest_"
    long number = 0;   // 44
};

std::optional<Numbered> numbered(const std::string& name) {
    std::size_t digits = name.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(name[digits - 1]))) --digits;
    if (digits == name.size() || digits == 0 || name.size() - digits > 9) return std::nullopt;
    return Numbered{name.substr(0, digits), std::stol(name.substr(digits))};
}

bool has(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

// 3D Gaussian splatting writes its splats as PLY vertices with these fields
// (spherical-harmonic colour, opacity, log-scales, rotation quaternion).
bool is_gaussian_splatting(const std::vector<std::string>& names) {
    return has(names, "f_dc_0") && has(names, "opacity") && has(names, "scale_0") && has(names, "rot_0");
}

}  // namespace

std::string compact_names(const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t i = 0; i < names.size();) {
        std::size_t end = i + 1;
        const std::optional<Numbered> first = numbered(names[i]);
        if (first)
            while (end < names.size()) {
                const std::optional<Numbered> next = numbered(names[end]);
                if (!next || next->stem != first->stem || next->number != first->number + long(end - i)) break;
                ++end;
            }
        text += text.empty() ? "" : ", ";
        if (end - i >= 3) text += names[i] + ".." + std::to_string(first->number + long(end - i - 1));
        else {
            for (std::size_t k = i; k < end; ++k) text += (k > i ? ", " : "") + names[k];
        }
        i = end;
    }
    return text;
}

std::vector<std::string> skipped_warnings(const Header& header, const VertexColumns& columns,
                                          const std::string& source) {
    std::vector<std::string> warnings;
    if (!columns.unused_properties.empty())
        warnings.push_back(source + ": ignored vertex properties (lists): " + compact_names(columns.unused_properties));
    std::vector<std::string> kept;
    for (const SphereProperty& property : columns.properties) kept.push_back(property.name);
    if (is_gaussian_splatting(kept))
        warnings.push_back(source + ": a 3D Gaussian splatting file: Orb renders neither its spherical-harmonic "
                                    "colours nor its log-scales, so its points are grey, sized by --radius or the "
                                    "derived radius (its fields are kept as sphere properties)");
    std::string elements;
    for (const Element& element : header.elements)
        if (element.name != "vertex" && element.count > 0)
            elements += (elements.empty() ? "" : ", ") + element.name + " (" + std::to_string(element.count) +
                        (element.count == 1 ? " row)" : " rows)");
    if (!elements.empty()) warnings.push_back(source + ": ignored elements: " + elements);
    if (columns.trailing_bytes > 0)
        warnings.push_back(source + ": ignored " + std::to_string(columns.trailing_bytes) +
                           (columns.trailing_bytes == 1 ? " byte" : " bytes") + " after the last element");
    return warnings;
}

std::string why_no_points(const Header& header) {
    std::string why = "it has no 'vertex' element";
    for (const Element& element : header.elements)
        if (element.name == "vertex") why = "its 'vertex' element has 0 rows";
    const std::string note = unknown_lines_note(header);
    return note.empty() ? why : why + " (" + note + ")";
}

}  // namespace orb::ply
