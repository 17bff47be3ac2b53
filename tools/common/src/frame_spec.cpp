#include "orb/cli/frame_spec.h"

#include <algorithm>
#include <charconv>
#include <string>
#include <unordered_set>

#include "orb/cli/tool_main.h"

namespace orb::cli {
namespace {

constexpr const char* kSpecForms = "expected N, A-B, A-BxSTEP or a comma-separated list such as 1,5,9-12";

[[noreturn]] void bad_spec(std::string_view whole, const std::string& why) {
    throw UsageError("frame list '" + std::string(whole) + "': " + why + "; " + kSpecForms);
}

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
    return text;
}

// A whole number written with digits only: no sign, no spaces, no "0x".
int parse_frame_number(std::string_view digits, std::string_view whole, const char* what, int most) {
    if (digits.empty()) bad_spec(whole, std::string("missing ") + what);
    for (char c : digits)
        if (c < '0' || c > '9') bad_spec(whole, "'" + std::string(digits) + "' is not a whole number (" + what + ")");
    long long value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec != std::errc() || end != digits.data() + digits.size() || value > most)
        bad_spec(whole, std::string(what) + " " + std::string(digits) + " is larger than " + std::to_string(most));
    return static_cast<int>(value);
}

struct Item {
    int first = 0, last = 0, step = 1;
};

Item parse_item(std::string_view item, std::string_view whole) {
    Item out;
    const auto x = item.find('x');
    std::string_view range = item.substr(0, x);
    if (x != std::string_view::npos)
        out.step = parse_frame_number(item.substr(x + 1), whole, "step", kMaxFrameNumber);
    const auto dash = range.find('-');
    if (dash == std::string_view::npos) {
        if (x != std::string_view::npos) bad_spec(whole, "a step needs a range A-B before the x");
        out.first = out.last = parse_frame_number(range, whole, "frame", kMaxFrameNumber);
        return out;
    }
    out.first = parse_frame_number(range.substr(0, dash), whole, "first frame", kMaxFrameNumber);
    out.last = parse_frame_number(range.substr(dash + 1), whole, "last frame", kMaxFrameNumber);
    if (out.last < out.first)
        bad_spec(whole, "the range " + std::string(range) + " ends before it starts");
    if (out.step < 1) bad_spec(whole, "the step must be at least 1");
    return out;
}

// Walks `pattern`, handing literal text to `on_text` and each frame-number
// field's zero-padding width to `on_field`.
template <class OnText, class OnField>
void scan_pattern(std::string_view pattern, OnText on_text, OnField on_field) {
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        const char c = pattern[i];
        if (c == '#') {
            std::size_t run = 1;
            while (i + run < pattern.size() && pattern[i + run] == '#') ++run;
            on_field(static_cast<int>(run));
            i += run - 1;
            continue;
        }
        if (c != '%') {
            on_text(c);
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            on_text('%');
            ++i;
            continue;
        }
        // %d or %0Nd with one digit N: a space-padded %4d would put spaces in file names.
        std::size_t j = i + 1;
        int width = 0;
        if (j + 1 < pattern.size() && pattern[j] == '0' && pattern[j + 1] >= '1' && pattern[j + 1] <= '9') {
            width = pattern[j + 1] - '0';
            j += 2;
        }
        if (j >= pattern.size() || pattern[j] != 'd')
            throw UsageError("'" + std::string(pattern) +
                             "': the only % conversions in a frame pattern are %d and %0Nd (N = 1 ... 9); write %% for a literal %");
        on_field(width);
        i = j;
    }
}

}  // namespace

FrameSpec parse_frame_spec(std::string_view text) {
    FrameSpec spec;
    if (trimmed(text).empty()) bad_spec(text, "it is empty");
    std::unordered_set<int> seen;
    std::string_view rest = text;
    while (true) {
        const auto comma = rest.find(',');
        const std::string_view item = trimmed(rest.substr(0, comma));
        if (item.empty()) bad_spec(text, "an empty item between commas");
        const Item range = parse_item(item, text);
        spec.lowest = spec.frames.empty() ? range.first : std::min(spec.lowest, range.first);
        spec.highest = spec.frames.empty() ? range.last : std::max(spec.highest, range.last);
        // Step from the first frame; `last - frame >= step` avoids overflowing past kMaxFrameNumber.
        for (int frame = range.first;; frame += range.step) {
            if (seen.insert(frame).second) {
                if (spec.frames.size() == kMaxFrameCount)
                    bad_spec(text, "more than " + std::to_string(kMaxFrameCount) + " frames");
                spec.frames.push_back(frame);
            }
            if (range.last - frame < range.step) break;
        }
        if (comma == std::string_view::npos) break;
        rest.remove_prefix(comma + 1);
    }
    return spec;
}

int count_frame_fields(std::string_view pattern) {
    int fields = 0;
    scan_pattern(pattern, [](char) {}, [&](int) { ++fields; });
    return fields;
}

std::string expand_frame_pattern(std::string_view pattern, int frame) {
    if (frame < 0) throw UsageError("frame " + std::to_string(frame) + " is negative");
    std::string out;
    int fields = 0;
    const std::string number = std::to_string(frame);
    scan_pattern(
        pattern, [&](char c) { out += c; },
        [&](int width) {
            if (static_cast<int>(number.size()) < width) out.append(width - number.size(), '0');
            out += number;
            ++fields;
        });
    if (fields == 0)
        throw UsageError("'" + std::string(pattern) +
                         "' has no frame number: put %04d (or ####) where the frame number goes, e.g. beauty.%04d.exr");
    return out;
}

}  // namespace orb::cli
