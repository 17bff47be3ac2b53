// The PLY data section: one cursor for ASCII tokens and binary scalars of
// either byte order, the vertex columns picked out by property name.
#include "ply_read.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "orb/scene/detail/json_text.h"
#include "orb/scene/error.h"

namespace orb::ply {
namespace {

// What went wrong with one value; the element loop adds where it happened.
struct DataProblem {
    std::string message;
};

class DataCursor {
public:
    DataCursor(std::string_view data, Encoding encoding) : data_(data), encoding_(encoding) {}

    double value(ScalarType type) {
        return encoding_ == Encoding::Ascii ? ascii_value(type) : binary_value(type);
    }

    std::uint64_t list_count(ScalarType type) {
        const double count = value(type);
        if (count < 0) throw DataProblem{"a negative list count (" + detail::format_number(count) + ")"};
        return static_cast<std::uint64_t>(count);
    }

    void skip(ScalarType type, std::uint64_t count) {
        if (encoding_ == Encoding::Ascii) {
            for (std::uint64_t i = 0; i < count; ++i) ascii_value(type);
            return;
        }
        const std::uint64_t remaining = data_.size() - position_;
        if (count > remaining / scalar_size(type)) throw DataProblem{"the data ends early (the file is truncated)"};
        position_ += count * scalar_size(type);
    }

    // Bytes not read yet; for ASCII data, those after the next white space.
    std::size_t remaining() {
        if (encoding_ == Encoding::Ascii)
            while (position_ < data_.size() && is_space(data_[position_])) ++position_;
        return data_.size() - position_;
    }

private:
    template <typename T>
    T load() {
        if (data_.size() - position_ < sizeof(T)) throw DataProblem{"the data ends early (the file is truncated)"};
        T value;
        std::memcpy(&value, data_.data() + position_, sizeof(T));
        position_ += sizeof(T);
        const bool file_is_little = encoding_ == Encoding::BinaryLittleEndian;
        if (file_is_little != (std::endian::native == std::endian::little)) value = byteswap(value);
        return value;
    }

    template <typename T>
    static T byteswap(T value) {
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
        std::memcpy(&value, bytes, sizeof(T));
        return value;
    }

    double binary_value(ScalarType type) {
        switch (type) {
            case ScalarType::Int8: return load<std::int8_t>();
            case ScalarType::UInt8: return load<std::uint8_t>();
            case ScalarType::Int16: return load<std::int16_t>();
            case ScalarType::UInt16: return load<std::uint16_t>();
            case ScalarType::Int32: return load<std::int32_t>();
            case ScalarType::UInt32: return load<std::uint32_t>();
            case ScalarType::Float32: return load<float>();
            case ScalarType::Float64: return load<double>();
        }
        return 0;
    }

    std::string_view next_token() {
        while (position_ < data_.size() && is_space(data_[position_])) ++position_;
        const std::size_t start = position_;
        while (position_ < data_.size() && !is_space(data_[position_])) ++position_;
        if (position_ == start) throw DataProblem{"the data ends early (the file is truncated)"};
        return data_.substr(start, position_ - start);
    }

    static bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

    double ascii_value(ScalarType type) {
        const std::string_view token = next_token();
        const char* first = token.data();
        const char* last = token.data() + token.size();
        if (*first == '+') ++first;  // from_chars refuses a leading '+', which PLY writers may print
        if (is_integer(type)) {
            long long integer = 0;
            const auto [rest, error] = std::from_chars(first, last, integer);
            if (error != std::errc() || rest != last || !fits(type, integer))
                throw DataProblem{"expected a " + std::string(scalar_name(type)) + ", got '" + clip(token) + "'"};
            return static_cast<double>(integer);
        }
        double number = 0;
        const auto [rest, error] = std::from_chars(first, last, number);
        if (error == std::errc::result_out_of_range) throw DataProblem{"'" + clip(token) + "' overflows a double"};
        if (error != std::errc() || rest != last)
            throw DataProblem{"expected a number, got '" + clip(token) + "'"};
        // The value a binary file of the same type would hold, so ASCII and binary agree.
        if (type == ScalarType::Float32) return static_cast<double>(static_cast<float>(number));
        return number;
    }

    static bool fits(ScalarType type, long long value) {
        switch (type) {
            case ScalarType::Int8: return value >= INT8_MIN && value <= INT8_MAX;
            case ScalarType::UInt8: return value >= 0 && value <= UINT8_MAX;
            case ScalarType::Int16: return value >= INT16_MIN && value <= INT16_MAX;
            case ScalarType::UInt16: return value >= 0 && value <= UINT16_MAX;
            case ScalarType::Int32: return value >= INT32_MIN && value <= INT32_MAX;
            case ScalarType::UInt32: return value >= 0 && value <= static_cast<long long>(UINT32_MAX);
            default: return true;
        }
    }

    static std::string clip(std::string_view token) {
        std::string text;
        for (char c : token.substr(0, 40)) text += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
        return token.size() > 40 ? text + "..." : text;
    }

    std::string_view data_;
    Encoding encoding_;
    std::size_t position_ = 0;
};

// What each vertex property is for.
enum class Role { Skip, X, Y, Z, Radius, Red, Green, Blue, Property };

struct VertexLayout {
    std::vector<Role> roles;  // one per property
    std::vector<std::size_t> column;  // Role::Property: its index in VertexColumns::properties
    bool has_radius = false;
    bool has_color = false;
    double color_divisor[3] = {1, 1, 1};  // stored value / divisor is in [0, 1]
};

// Integer colours are fractions of their type's largest value (255 for uchar).
double color_divisor(ScalarType type) {
    switch (type) {
        case ScalarType::Int8:
        case ScalarType::UInt8: return 255.0;
        case ScalarType::Int16:
        case ScalarType::UInt16: return 65535.0;
        case ScalarType::Int32:
        case ScalarType::UInt32: return 4294967295.0;
        default: return 1.0;
    }
}

VertexLayout vertex_layout(const Element& vertex, const std::string& source) {
    VertexLayout layout;
    layout.roles.assign(vertex.properties.size(), Role::Skip);
    auto find = [&](std::string_view name) -> int {
        for (std::size_t i = 0; i < vertex.properties.size(); ++i)
            if (vertex.properties[i].name == name) return static_cast<int>(i);
        return -1;
    };
    auto assign = [&](int index, Role role) {
        const Property& property = vertex.properties[static_cast<std::size_t>(index)];
        if (property.is_list)
            throw InputError(source + ":" + std::to_string(property.line) + ": vertex property '" + property.name +
                             "' must be a single value, not a list");
        layout.roles[static_cast<std::size_t>(index)] = role;
    };
    const char* axes[] = {"x", "y", "z"};
    const Role axis_roles[] = {Role::X, Role::Y, Role::Z};
    for (int axis = 0; axis < 3; ++axis) {
        const int index = find(axes[axis]);
        if (index < 0)
            throw InputError(source + ":" + std::to_string(vertex.line) + ": element 'vertex' has no '" + axes[axis] +
                             "' property (x, y and z are required)");
        assign(index, axis_roles[axis]);
    }
    int radius = find("radius");
    if (radius < 0) radius = find("scale");
    if (radius >= 0) {
        assign(radius, Role::Radius);
        layout.has_radius = true;
    }
    // The first complete set of colour names wins.
    const char* color_sets[][3] = {{"red", "green", "blue"}, {"r", "g", "b"}, {"diffuse_red", "diffuse_green", "diffuse_blue"}};
    const Role color_roles[] = {Role::Red, Role::Green, Role::Blue};
    for (const auto& names : color_sets) {
        const int indices[3] = {find(names[0]), find(names[1]), find(names[2])};
        if (indices[0] < 0 || indices[1] < 0 || indices[2] < 0) continue;
        for (int c = 0; c < 3; ++c) {
            assign(indices[c], color_roles[c]);
            layout.color_divisor[c] = color_divisor(vertex.properties[static_cast<std::size_t>(indices[c])].type);
        }
        layout.has_color = true;
        break;
    }
    // The rest that are single values become the spheres' named properties.
    layout.column.assign(vertex.properties.size(), 0);
    std::size_t columns = 0;
    for (std::size_t i = 0; i < vertex.properties.size(); ++i) {
        if (layout.roles[i] != Role::Skip || vertex.properties[i].is_list) continue;
        layout.roles[i] = Role::Property;
        layout.column[i] = columns++;
    }
    return layout;
}

std::vector<std::string> unused_properties(const Element& vertex, const VertexLayout& layout) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < vertex.properties.size(); ++i)
        if (layout.roles[i] == Role::Skip) names.push_back(vertex.properties[i].name);
    return names;
}

// Refuses counts the data cannot hold before anything is allocated: each
// binary row takes at least its fixed-size part, each ASCII value one byte.
void check_counts_fit(const Header& header, std::size_t data_size, const std::string& source) {
    std::uint64_t remaining = data_size;
    for (const Element& element : header.elements) {
        std::uint64_t row_bytes = 0;
        for (const Property& property : element.properties) {
            if (header.encoding == Encoding::Ascii) row_bytes += 1;
            else row_bytes += scalar_size(property.is_list ? property.count_type : property.type);
        }
        if (row_bytes == 0) continue;
        if (element.count > remaining / row_bytes)
            throw InputError(source + ":" + std::to_string(element.line) + ": element '" + element.name + "' declares " +
                             std::to_string(element.count) + " rows of at least " + std::to_string(row_bytes) +
                             " bytes, more than the " + std::to_string(remaining) + " bytes of data left in the file");
        remaining -= element.count * row_bytes;
    }
}

void read_vertex_row(DataCursor& cursor, const Element& vertex, const VertexLayout& layout, VertexColumns& columns,
                     std::size_t& property_index) {
    Vec3 center{}, color{};
    double radius = 0;
    for (property_index = 0; property_index < vertex.properties.size(); ++property_index) {
        const Property& property = vertex.properties[property_index];
        if (property.is_list) {
            cursor.skip(property.type, cursor.list_count(property.count_type));
            continue;
        }
        const double value = cursor.value(property.type);
        switch (layout.roles[property_index]) {
            case Role::Skip: break;
            case Role::X: center[0] = value; break;
            case Role::Y: center[1] = value; break;
            case Role::Z: center[2] = value; break;
            case Role::Radius: radius = value; break;
            case Role::Red: color[0] = value / layout.color_divisor[0]; break;
            case Role::Green: color[1] = value / layout.color_divisor[1]; break;
            case Role::Blue: color[2] = value / layout.color_divisor[2]; break;
            case Role::Property:
                columns.properties[layout.column[property_index]].values.push_back(static_cast<float>(value));
                break;
        }
        const Role role = layout.roles[property_index];
        if (role == Role::X || role == Role::Y || role == Role::Z) {
            if (!std::isfinite(value)) throw DataProblem{"must be finite, got " + detail::format_number(value)};
        } else if (role == Role::Radius) {
            if (!std::isfinite(value) || value <= 0)
                throw DataProblem{"must be > 0, got " + detail::format_number(value)};
        } else if (role == Role::Red || role == Role::Green || role == Role::Blue) {
            if (!(value >= 0) || value / layout.color_divisor[static_cast<int>(role) - static_cast<int>(Role::Red)] > 1)
                throw DataProblem{"colour must be in [0, 1] (0 .. 255 for uchar), got " + detail::format_number(value)};
        }
    }
    property_index = vertex.properties.size();
    columns.centers.push_back(center);
    if (layout.has_radius) columns.radii.push_back(radius);
    if (layout.has_color) columns.colors.push_back(color);
}

void skip_row(DataCursor& cursor, const Element& element, std::size_t& property_index) {
    for (property_index = 0; property_index < element.properties.size(); ++property_index) {
        const Property& property = element.properties[property_index];
        if (property.is_list) cursor.skip(property.type, cursor.list_count(property.count_type));
        else cursor.skip(property.type, 1);
    }
}

}  // namespace

VertexColumns read_vertices(std::string_view bytes, const Header& header, const std::string& source) {
    const Element* vertex = nullptr;
    for (const Element& element : header.elements)
        if (element.name == "vertex") vertex = &element;
    const VertexLayout layout = vertex ? vertex_layout(*vertex, source) : VertexLayout{};
    const std::string_view data = bytes.substr(header.data_offset);
    check_counts_fit(header, data.size(), source);

    VertexColumns columns;
    if (vertex) {
        // The count check above bounds these by the file size.
        columns.centers.reserve(vertex->count);
        if (layout.has_radius) columns.radii.reserve(vertex->count);
        if (layout.has_color) columns.colors.reserve(vertex->count);
        columns.unused_properties = unused_properties(*vertex, layout);
        for (std::size_t i = 0; i < vertex->properties.size(); ++i) {
            if (layout.roles[i] != Role::Property) continue;
            SphereProperty property;
            property.name = vertex->properties[i].name;
            property.values.reserve(vertex->count);
            columns.properties.push_back(std::move(property));
        }
    }

    DataCursor cursor(data, header.encoding);
    for (const Element& element : header.elements) {
        std::uint64_t row = 0;
        std::size_t property_index = 0;
        try {
            if (&element == vertex) {
                for (; row < element.count; ++row) read_vertex_row(cursor, element, layout, columns, property_index);
            } else if (!element.properties.empty()) {
                for (; row < element.count; ++row) skip_row(cursor, element, property_index);
            }
        } catch (const DataProblem& problem) {
            std::string where = source + ": " + element.name + " " + std::to_string(row);
            if (property_index < element.properties.size())
                where += " property '" + element.properties[property_index].name + "'";
            throw InputError(where + ": " + problem.message);
        }
    }
    columns.trailing_bytes = cursor.remaining();
    return columns;
}

}  // namespace orb::ply
