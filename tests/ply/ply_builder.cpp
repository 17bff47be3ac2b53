#include "ply_builder.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace orb::test {
namespace {

template <typename T>
void append_binary(std::string& out, double value, bool big_endian) {
    const T typed = static_cast<T>(value);
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &typed, sizeof(T));
    if (big_endian)  // the tests run on little-endian machines
        for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
    out.append(reinterpret_cast<const char*>(bytes), sizeof(T));
}

void append_value(std::string& out, const std::string& type, double value, const std::string& format) {
    if (format == "ascii") {
        char text[64];
        const bool integer = type != "float" && type != "float32" && type != "double" && type != "float64";
        if (integer) std::snprintf(text, sizeof text, "%lld ", static_cast<long long>(value));
        else std::snprintf(text, sizeof text, "%.17g ", value);
        out += text;
        return;
    }
    const bool big = format == "binary_big_endian";
    if (type == "char" || type == "int8") append_binary<std::int8_t>(out, value, big);
    else if (type == "uchar" || type == "uint8") append_binary<std::uint8_t>(out, value, big);
    else if (type == "short" || type == "int16") append_binary<std::int16_t>(out, value, big);
    else if (type == "ushort" || type == "uint16") append_binary<std::uint16_t>(out, value, big);
    else if (type == "int" || type == "int32") append_binary<std::int32_t>(out, value, big);
    else if (type == "uint" || type == "uint32") append_binary<std::uint32_t>(out, value, big);
    else if (type == "float" || type == "float32") append_binary<float>(out, value, big);
    else if (type == "double" || type == "float64") append_binary<double>(out, value, big);
    else throw std::invalid_argument("make_ply: unknown type " + type);
}

}  // namespace

std::string make_ply(const std::string& format, const std::vector<PlyTestElement>& elements) {
    std::string out = "ply\nformat " + format + " 1.0\ncomment written by the Orb tests\n";
    for (const PlyTestElement& element : elements) {
        out += "element " + element.name + " " + std::to_string(element.rows.size()) + "\n";
        for (const PlyTestProperty& p : element.properties) {
            if (p.list_count_type.empty()) out += "property " + p.type + " " + p.name + "\n";
            else out += "property list " + p.list_count_type + " " + p.type + " " + p.name + "\n";
        }
    }
    out += "end_header\n";
    for (const PlyTestElement& element : elements) {
        for (const std::vector<double>& row : element.rows) {
            std::size_t i = 0;
            for (const PlyTestProperty& p : element.properties) {
                if (p.list_count_type.empty()) {
                    append_value(out, p.type, row.at(i++), format);
                    continue;
                }
                const auto count = static_cast<std::size_t>(row.at(i++));
                append_value(out, p.list_count_type, static_cast<double>(count), format);
                for (std::size_t k = 0; k < count; ++k) append_value(out, p.type, row.at(i++), format);
            }
            if (format == "ascii") out += "\n";
        }
    }
    return out;
}

}  // namespace orb::test
