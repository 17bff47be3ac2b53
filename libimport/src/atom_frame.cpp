#include "atom_frame.h"

#include <algorithm>
#include <cctype>

#include "line_reader.h"

namespace orb::molecular {

const Element& element_of_symbol(std::string_view text, std::unordered_map<std::string, std::size_t>& unknown) {
    if (const Element* element = find_element(text)) return *element;
    long long number = 0;
    if (parse_long(text, number))
        if (const Element* element = element_by_number(static_cast<long>(number))) return *element;
    ++unknown[std::string(text.substr(0, 16))];
    return unknown_element();
}

std::string unknown_elements_warning(const std::string& source,
                                     const std::unordered_map<std::string, std::size_t>& unknown) {
    if (unknown.empty()) return "";
    std::vector<std::pair<std::string, std::size_t>> sorted(unknown.begin(), unknown.end());
    std::sort(sorted.begin(), sorted.end());
    std::size_t atoms = 0;
    std::string names;
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        atoms += sorted[i].second;
        if (i < 8) names += (i ? ", " : "") + quoted_excerpt(sorted[i].first) + ": " + std::to_string(sorted[i].second);
    }
    if (sorted.size() > 8) names += ", ...";
    return source + ": " + std::to_string(atoms) + " atoms name no element of the table (" + names +
           "); they are drawn grey with radius " + std::to_string(static_cast<int>(kNoVdwRadius)) +
           " (the unknown element X)";
}

}  // namespace orb::molecular
