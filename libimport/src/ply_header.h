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

// A header line that starts with no PLY keyword, read as a comment: some
// writers put free text there (Blender 2.4x's exporter wrote "Created by
// Blender3D 243 - www.blender.org, ..." without the "comment" keyword).
struct UnknownLine {
    int line = 0;
    std::string text;
};

struct Header {
    Encoding encoding = Encoding::Ascii;
    std::vector<Element> elements;
    std::size_t data_offset = 0;  // first byte after the "end_header" line
    std::vector<UnknownLine> unknown_lines;
};

// What became of the header's unknown lines, for a warning, or for an error
// that one of them may explain (a misspelt "elemnt"): `line 3 ("Created by
// Blender3D ...") was read as a comment`; empty when there are none.
std::string unknown_lines_note(const Header& header);

std::size_t scalar_size(ScalarType type);
bool is_integer(ScalarType type);
const char* scalar_name(ScalarType type);

// Throws InputError("source:line: ...") for a malformed header; the message
// names any unknown lines read as comments before the problem.
Header parse_header(std::string_view bytes, const std::string& source);

}  // namespace orb::ply
