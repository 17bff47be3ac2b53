// The header of a PLY file: its encoding, and the elements with their
// properties in file order, which is all it takes to walk the data.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace orb::ply {

enum class Encoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

enum class ScalarType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct Property {
    std::string name;
    ScalarType type = ScalarType::Float32;  // of the value, or of each list item
    bool is_list = false;
    ScalarType count_type = ScalarType::UInt8;  // lists only: an integer type
    int line = 0;                               // header line, for messages
};

struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> properties;
    int line = 0;
};

struct Header {
    Encoding encoding = Encoding::Ascii;
    std::vector<Element> elements;
    std::size_t data_offset = 0;  // first byte after the "end_header" line
};

std::size_t scalar_size(ScalarType type);
bool is_integer(ScalarType type);
const char* scalar_name(ScalarType type);

// Throws InputError("source:line: ...") for a malformed header.
Header parse_header(std::string_view bytes, const std::string& source);

}  // namespace orb::ply
