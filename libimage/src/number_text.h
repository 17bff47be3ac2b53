// Private: doubles as the shortest text that reads back to the same value,
// so that a recorded exposure compares exactly and reads as typed ("0.5").
#pragma once

#include <charconv>
#include <optional>
#include <string>

namespace orb::image {

inline std::string shortest_text(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

inline std::optional<double> parse_double(const std::string& text) {
    double value = 0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (result.ec != std::errc() || result.ptr != text.data() + text.size()) return std::nullopt;
    return value;
}

}  // namespace orb::image
