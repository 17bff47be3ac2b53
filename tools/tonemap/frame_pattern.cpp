#include "frame_pattern.h"

#include <cctype>
#include <string>

#include "orb/cli/tool_main.h"

namespace orb::tonemap {
namespace {

using orb::cli::UsageError;

long parse_number(const std::string& text, const std::string& whole) {
    if (text.empty()) throw UsageError("--frames: expected FIRST-LAST, got '" + whole + "'");
    for (char c : text)
        if (!std::isdigit(static_cast<unsigned char>(c)))
            throw UsageError("--frames: expected FIRST-LAST with non-negative integers, got '" + whole + "'");
    if (text.size() > 9) throw UsageError("--frames: frame number too large in '" + whole + "'");
    return std::stol(text);
}

// Calls `on_conversion(width)` for each %d / %0Nd; `on_text` for literal text.
template <class Text, class Conversion>
void scan(const std::string& pattern, Text on_text, Conversion on_conversion) {
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            on_text(pattern[i]);
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            on_text('%');
            ++i;
            continue;
        }
        size_t j = i + 1;
        std::string digits;
        while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) digits += pattern[j++];
        if (j >= pattern.size() || pattern[j] != 'd' || (!digits.empty() && digits[0] != '0'))
            throw UsageError("'" + pattern + "': only %d or %0Nd frame conversions are supported");
        if (digits.size() > 2) throw UsageError("'" + pattern + "': frame number width too large");
        on_conversion(digits.empty() ? 0 : std::stoi(digits));
        i = j;
    }
}

}  // namespace

FrameRange parse_frame_range(const std::string& text) {
    FrameRange range;
    const auto dash = text.find('-');
    if (dash == std::string::npos) {
        range.first = range.last = parse_number(text, text);
    } else {
        range.first = parse_number(text.substr(0, dash), text);
        range.last = parse_number(text.substr(dash + 1), text);
    }
    if (range.last < range.first) throw UsageError("--frames: last frame comes before the first in '" + text + "'");
    return range;
}

bool is_frame_pattern(const std::string& pattern) {
    int conversions = 0;
    try {
        scan(pattern, [](char) {}, [&](int) { ++conversions; });
    } catch (const UsageError&) {
        return false;
    }
    return conversions == 1;
}

std::string expand_frame_pattern(const std::string& pattern, long frame) {
    std::string out;
    int conversions = 0;
    scan(
        pattern, [&](char c) { out += c; },
        [&](int width) {
            std::string number = std::to_string(frame);
            if (static_cast<int>(number.size()) < width) number.insert(0, width - number.size(), '0');
            out += number;
            ++conversions;
        });
    if (conversions != 1) throw UsageError("'" + pattern + "' must contain exactly one %d or %0Nd frame number");
    return out;
}

}  // namespace orb::tonemap
