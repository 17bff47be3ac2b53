// The start of a text input, for recognising formats by their first bytes.
#pragma once

#include <string_view>
#include <vector>

namespace orb::detail {

// How much of an input recognising reads: its formats show themselves in
// their first lines.
inline constexpr std::size_t kRecognisedHead = 65536;

// `bytes` after a UTF-8 byte-order mark and leading white space (space, tab, CR, LF).
inline std::string_view skip_bom_and_space(std::string_view bytes) {
    if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
    while (!bytes.empty() && (bytes.front() == ' ' || bytes.front() == '\t' || bytes.front() == '\r' ||
                              bytes.front() == '\n'))
        bytes.remove_prefix(1);
    return bytes;
}

// The start of an input as recognising reads it: its first kRecognisedHead
// bytes after a byte-order mark and leading white space.
inline std::string_view recognised_head(std::string_view bytes) {
    return skip_bom_and_space(bytes.substr(0, kRecognisedHead));
}

// The first line of `text`, without its line end.
inline std::string_view first_line(std::string_view text) {
    std::string_view line = text.substr(0, text.find('\n'));
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
}

// Up to `count` lines from the start of `text`.
inline std::vector<std::string_view> head_lines(std::string_view text, std::size_t count) {
    std::vector<std::string_view> lines;
    while (lines.size() < count && !text.empty()) {
        lines.push_back(first_line(text));
        const std::size_t next = text.find('\n');
        if (next == std::string_view::npos) break;
        text.remove_prefix(next + 1);
    }
    return lines;
}

// Whether `word` is a count: decimal digits only.
inline bool is_count_word(std::string_view word) {
    if (word.empty()) return false;
    for (char c : word)
        if (c < '0' || c > '9') return false;
    return true;
}

}  // namespace orb::detail
