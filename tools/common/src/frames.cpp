#include "orb/cli/frames.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "orb/cli/tool_main.h"

namespace orb::cli {
namespace {

long parse_frame_number(const std::string& text, const std::string& entry, const std::string& option) {
    if (text.empty() || !std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); }))
        throw UsageError(option + ": expected frame numbers like 12, 1-240, 1-240x2 or 1,5,9-12, got '" + entry +
                         "'");
    if (text.size() > 9) throw UsageError(option + ": frame number too large in '" + entry + "' (at most 999999999)");
    return std::stol(text);
}

// Calls on_text(c) for literal characters and on_number(width) for each frame
// number: %d (width 0), %0Nd (width N) or a run of N '#' (width N).
template <class Text, class Number>
void scan(const std::string& pattern, Text on_text, Number on_number) {
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] == '#') {
            std::size_t j = i;
            while (j < pattern.size() && pattern[j] == '#') ++j;
            on_number(static_cast<int>(j - i));
            i = j - 1;
            continue;
        }
        if (pattern[i] != '%') {
            on_text(pattern[i]);
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            on_text('%');
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        std::string digits;
        while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) digits += pattern[j++];
        if (j >= pattern.size() || pattern[j] != 'd' || (!digits.empty() && digits[0] != '0'))
            throw UsageError("'" + pattern + "': a frame number is %d, %0Nd or ####; write %% for a literal %");
        if (digits.size() > 2) throw UsageError("'" + pattern + "': frame number width too large");
        on_number(digits.empty() ? 0 : std::stoi(digits));
        i = j;
    }
}

}  // namespace

std::vector<long> parse_frame_list(const std::string& spec, const std::string& option) {
    std::vector<long> frames;
    std::set<long> seen;
    std::size_t start = 0;
    while (start <= spec.size()) {
        std::size_t comma = spec.find(',', start);
        if (comma == std::string::npos) comma = spec.size();
        const std::string entry = spec.substr(start, comma - start);
        start = comma + 1;

        std::string range = entry;
        long step = 1;
        if (const auto x = entry.find('x'); x != std::string::npos) {
            range = entry.substr(0, x);
            step = parse_frame_number(entry.substr(x + 1), entry, option);
            if (step < 1) throw UsageError(option + ": the step must be at least 1 in '" + entry + "'");
            if (range.find('-') == std::string::npos)
                throw UsageError(option + ": a step needs a range, like 1-240x2, got '" + entry + "'");
        }
        long first = 0, last = 0;
        if (const auto dash = range.find('-'); dash != std::string::npos) {
            first = parse_frame_number(range.substr(0, dash), entry, option);
            last = parse_frame_number(range.substr(dash + 1), entry, option);
            if (last < first) throw UsageError(option + ": the last frame comes before the first in '" + entry + "'");
        } else {
            first = last = parse_frame_number(range, entry, option);
        }
        for (long frame = first; frame <= last; frame += step) {
            if (seen.insert(frame).second) frames.push_back(frame);
            if (frames.size() > kMaxFrames)
                throw UsageError(option + ": more than " + std::to_string(kMaxFrames) + " frames in '" + spec + "'");
        }
    }
    return frames;
}

bool has_frame_number(const std::string& pattern) {
    int numbers = 0;
    try {
        scan(pattern, [](char) {}, [&](int) { ++numbers; });
    } catch (const UsageError&) {
        return false;
    }
    return numbers == 1;
}

std::string expand_frame_pattern(const std::string& pattern, long frame) {
    std::string out;
    int numbers = 0;
    scan(
        pattern, [&](char c) { out += c; },
        [&](int width) {
            std::string digits = std::to_string(frame);
            if (static_cast<int>(digits.size()) < width) digits.insert(0, width - digits.size(), '0');
            out += digits;
            ++numbers;
        });
    if (numbers != 1)
        throw UsageError("'" + pattern + "' must hold exactly one frame number (%04d, %d or ####), it holds " +
                         std::to_string(numbers));
    return out;
}

}  // namespace orb::cli
