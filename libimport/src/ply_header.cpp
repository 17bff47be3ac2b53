// Parses the PLY header line by line; every complaint names its line.
#include "ply_header.h"

#include <charconv>
#include <set>

#include "orb/scene/error.h"

namespace orb::ply {
namespace {

struct NamedType {
    std::string_view name;
    ScalarType type;
};

// The original PLY names and the sized aliases most writers use today.
constexpr NamedType kTypeNames[] = {
    {"char", ScalarType::Int8},     {"int8", ScalarType::Int8},       {"uchar", ScalarType::UInt8},
    {"uint8", ScalarType::UInt8},   {"short", ScalarType::Int16},     {"int16", ScalarType::Int16},
    {"ushort", ScalarType::UInt16}, {"uint16", ScalarType::UInt16},   {"int", ScalarType::Int32},
    {"int32", ScalarType::Int32},   {"uint", ScalarType::UInt32},     {"uint32", ScalarType::UInt32},
    {"float", ScalarType::Float32}, {"float32", ScalarType::Float32}, {"double", ScalarType::Float64},
    {"float64", ScalarType::Float64},
};

std::string printable(std::string_view line);

[[noreturn]] void fail(const std::string& source, int line, const std::string& message) {
    throw InputError(source + ":" + std::to_string(line) + ": " + message);
}

// A header problem after unknown lines: one of them may be the cause.
[[noreturn]] void fail(const std::string& source, int line, const std::string& message, const Header& header) {
    const std::string note = unknown_lines_note(header);
    fail(source, line, note.empty() ? message : message + " (" + note + ")");
}

std::vector<std::string_view> split_words(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

ScalarType parse_type(std::string_view word, const std::string& source, int line) {
    for (const NamedType& named : kTypeNames)
        if (named.name == word) return named.type;
    fail(source, line,
         "unknown property type '" + std::string(word) +
             "' (expected char, uchar, short, ushort, int, uint, float, double or int8 ... float64)");
}

std::string printable(std::string_view line) {
    std::string text;
    for (char c : line.substr(0, 80)) text += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
    return line.size() > 80 ? text + "..." : text;
}

}  // namespace

std::string unknown_lines_note(const Header& header) {
    const std::vector<UnknownLine>& lines = header.unknown_lines;
    if (lines.empty()) return "";
    std::string text = lines.size() == 1 ? "line " : "lines ";
    for (std::size_t i = 0; i < lines.size() && i < 3; ++i)
        text += (i ? ", " : "") + std::to_string(lines[i].line) + " (\"" + printable(lines[i].text) + "\")";
    if (lines.size() > 3) text += " and " + std::to_string(lines.size() - 3) + " more";
    return text + (lines.size() == 1 ? " has no PLY keyword and was read as a comment"
                                     : " have no PLY keyword and were read as comments");
}

std::size_t scalar_size(ScalarType type) {
    switch (type) {
        case ScalarType::Int8:
        case ScalarType::UInt8: return 1;
        case ScalarType::Int16:
        case ScalarType::UInt16: return 2;
        case ScalarType::Int32:
        case ScalarType::UInt32:
        case ScalarType::Float32: return 4;
        case ScalarType::Float64: return 8;
    }
    return 1;
}

bool is_integer(ScalarType type) { return type != ScalarType::Float32 && type != ScalarType::Float64; }

const char* scalar_name(ScalarType type) {
    switch (type) {
        case ScalarType::Int8: return "char";
        case ScalarType::UInt8: return "uchar";
        case ScalarType::Int16: return "short";
        case ScalarType::UInt16: return "ushort";
        case ScalarType::Int32: return "int";
        case ScalarType::UInt32: return "uint";
        case ScalarType::Float32: return "float";
        case ScalarType::Float64: return "double";
    }
    return "?";
}

Header parse_header(std::string_view bytes, const std::string& source) {
    Header header;
    bool have_format = false;
    std::size_t position = 0;
    for (int line_number = 1;; ++line_number) {
        const std::size_t end = bytes.find('\n', position);
        if (end == std::string_view::npos)
            fail(source, line_number, "the header ends without an \"end_header\" line", header);
        std::string_view line = bytes.substr(position, end - position);
        position = end + 1;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // files written on Windows
        if (line.find('\0') != std::string_view::npos)
            fail(source, line_number, "a NUL byte in the header (is the file truncated or not PLY?)", header);

        if (line_number == 1) {
            if (line != "ply") fail(source, 1, "expected the magic line \"ply\", got \"" + printable(line) + "\"");
            continue;
        }
        const std::vector<std::string_view> words = split_words(line);
        // A blank line has no keyword either: read as a comment, like any line without one.
        const std::string_view keyword = words.empty() ? std::string_view{} : words[0];

        if (keyword == "comment" || keyword == "obj_info") continue;
        if (keyword == "end_header") {
            if (words.size() != 1) fail(source, line_number, "\"end_header\" takes nothing after it", header);
            if (!have_format) fail(source, line_number, "the header has no \"format\" line", header);
            header.data_offset = position;
            return header;
        }
        if (keyword == "format") {
            if (have_format) fail(source, line_number, "a second \"format\" line", header);
            if (words.size() != 3) fail(source, line_number, "expected \"format ENCODING 1.0\"", header);
            if (words[1] == "ascii") header.encoding = Encoding::Ascii;
            else if (words[1] == "binary_little_endian") header.encoding = Encoding::BinaryLittleEndian;
            else if (words[1] == "binary_big_endian") header.encoding = Encoding::BinaryBigEndian;
            else
                fail(source, line_number,
                     "unknown encoding '" + std::string(words[1]) +
                         "' (expected ascii, binary_little_endian or binary_big_endian)", header);
            if (words[2] != "1.0") fail(source, line_number, "unsupported PLY version '" + std::string(words[2]) + "' (expected 1.0)", header);
            have_format = true;
            continue;
        }
        if (keyword == "element") {
            if (words.size() != 3) fail(source, line_number, "expected \"element NAME COUNT\"", header);
            Element element;
            element.name = std::string(words[1]);
            element.line = line_number;
            const std::string_view count = words[2];
            const auto [rest, error] = std::from_chars(count.data(), count.data() + count.size(), element.count);
            if (error == std::errc::result_out_of_range)
                fail(source, line_number, "element '" + element.name + "' count " + std::string(count) + " overflows", header);
            if (error != std::errc() || rest != count.data() + count.size())
                fail(source, line_number,
                     "element '" + element.name + "' count must be a non-negative integer, got '" + std::string(count) + "'", header);
            for (const Element& other : header.elements)
                if (other.name == element.name) fail(source, line_number, "a second element named '" + element.name + "'", header);
            header.elements.push_back(std::move(element));
            continue;
        }
        if (keyword == "property") {
            if (header.elements.empty()) fail(source, line_number, "a property before any \"element\" line", header);
            Property property;
            property.line = line_number;
            if (words.size() >= 2 && words[1] == "list") {
                if (words.size() != 5) fail(source, line_number, "expected \"property list COUNT_TYPE ITEM_TYPE NAME\"", header);
                property.is_list = true;
                property.count_type = parse_type(words[2], source, line_number);
                if (!is_integer(property.count_type))
                    fail(source, line_number, "a list count type must be an integer type, got '" + std::string(words[2]) + "'", header);
                property.type = parse_type(words[3], source, line_number);
                property.name = std::string(words[4]);
            } else {
                if (words.size() != 3) fail(source, line_number, "expected \"property TYPE NAME\"", header);
                property.type = parse_type(words[1], source, line_number);
                property.name = std::string(words[2]);
            }
            Element& element = header.elements.back();
            for (const Property& other : element.properties)
                if (other.name == property.name)
                    fail(source, line_number, "element '" + element.name + "' has a second property '" + property.name + "'", header);
            element.properties.push_back(std::move(property));
            continue;
        }
        header.unknown_lines.push_back({line_number, std::string(line)});
    }
}

}  // namespace orb::ply
