// Writes small PLY files for tests, the same rows in any of the three
// encodings, so the reader's results can be compared across them.
#pragma once

#include <string>
#include <vector>

namespace orb::test {

struct PlyTestProperty {
    std::string type;             // "float", "uchar", "int16", ... (item type for lists)
    std::string name;
    std::string list_count_type;  // empty: a single value; else a list with counts of this type
};

struct PlyTestElement {
    std::string name;
    std::vector<PlyTestProperty> properties;
    // One vector per row, values in property order; a list is its count
    // followed by its items.
    std::vector<std::vector<double>> rows;
};

// `format`: "ascii", "binary_little_endian" or "binary_big_endian".
std::string make_ply(const std::string& format, const std::vector<PlyTestElement>& elements);

}  // namespace orb::test
