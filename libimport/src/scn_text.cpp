#include "scn_text.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <system_error>

#include "orb/scene/error.h"

namespace orb::scn {
namespace {

bool is_separator(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

bool is_text_byte(unsigned char c) {
    return (c >= 0x20 && c < 0x7f) || c == '\n' || is_separator(static_cast<char>(c));
}

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

}  // namespace

std::string quoted_word(std::string_view text) {
    constexpr size_t kMaxShown = 32;
    std::string out = "'";
    for (size_t i = 0; i < text.size() && i < kMaxShown; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02X", c);
            out += escaped;
        }
    }
    if (text.size() > kMaxShown) out += "...";
    return out + "'";
}

std::string_view require_text(std::string_view bytes, const std::string& source) {
    size_t skipped = 0;
    if (bytes.substr(0, kByteOrderMark.size()) == kByteOrderMark) skipped = kByteOrderMark.size();
    int line = 1;
    int column = 1 + static_cast<int>(skipped);
    for (size_t i = skipped; i < bytes.size(); ++i) {
        const auto c = static_cast<unsigned char>(bytes[i]);
        if (!is_text_byte(c)) {
            char shown[8];
            std::snprintf(shown, sizeof shown, "0x%02X", c);
            throw_at(source, line, column,
                     std::string("expected plain ASCII text, found byte ") + shown +
                         (c == 0 ? " (a NUL byte: binary data?)" : ""));
        }
        if (c == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return bytes.substr(skipped);
}

LineReader::LineReader(std::string_view text, int first_column_offset)
    : text_(text), first_column_offset_(first_column_offset) {
    // The end of input: on the line after a final newline, else just past the last byte.
    const size_t last_newline = text.rfind('\n');
    end_line_ = 1;
    for (char c : text) end_line_ += c == '\n' ? 1 : 0;
    const size_t last_line_start = last_newline == std::string_view::npos ? 0 : last_newline + 1;
    end_column_ = static_cast<int>(text.size() - last_line_start) + 1 + (end_line_ == 1 ? first_column_offset : 0);
}

bool LineReader::next(Line& line) {
    while (position_ < text_.size()) {
        size_t end = text_.find('\n', position_);
        if (end == std::string_view::npos) end = text_.size();
        const std::string_view raw = text_.substr(position_, end - position_);
        position_ = end + 1;
        ++line_number_;

        const int column_offset = line_number_ == 1 ? first_column_offset_ : 0;
        line.number = line_number_;
        line.words.clear();
        line.end_column = 1 + column_offset;
        size_t i = 0;
        while (i < raw.size()) {
            while (i < raw.size() && is_separator(raw[i])) ++i;
            const size_t start = i;
            while (i < raw.size() && !is_separator(raw[i])) ++i;
            if (i > start) {
                line.words.push_back({raw.substr(start, i - start), line_number_,
                                      static_cast<int>(start) + 1 + column_offset});
                line.end_column = static_cast<int>(i) + 1 + column_offset;
            }
        }
        if (!line.words.empty()) return true;
    }
    return false;
}

double parse_number(const Word& word, const std::string& source, std::string_view what) {
    std::string_view digits = word.text;
    // strtod takes one leading '+'; from_chars does not, so skip it here ("+-1" stays invalid).
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    const auto fail = [&](const std::string& why) {
        throw_at(source, word.line, word.column,
                 "expected " + std::string(what) + " (a finite number), got " + quoted_word(word.text) + why);
    };
    if (digits.empty() || digits.front() == '+' || (word.text.front() == '+' && digits.front() == '-')) fail("");

    double value = 0.0;
    // chars_format::general is strtod's decimal syntax without hexadecimal.
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value,
                                           std::chars_format::general);
    if (ec == std::errc::invalid_argument || end != digits.data() + digits.size()) fail("");
    if (ec == std::errc::result_out_of_range) {
        // Either overflow (an error) or underflow, which strtod rounds to zero
        // or a subnormal: let strtod decide on a bounded, NUL-terminated copy.
        const std::string copy(digits);
        value = std::strtod(copy.c_str(), nullptr);
        if (!std::isfinite(value)) fail(" (out of range for a double)");
    }
    if (!std::isfinite(value)) fail(" (not finite)");
    return value;
}

std::uint64_t parse_count(const Word& word, const std::string& source, std::string_view what,
                          std::uint64_t max) {
    std::string_view digits = word.text;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value, 10);
    const bool all_digits = !digits.empty() && end == digits.data() + digits.size() &&
                            digits.front() >= '0' && digits.front() <= '9';
    if (!all_digits || (ec != std::errc() && ec != std::errc::result_out_of_range))
        throw_at(source, word.line, word.column,
                 "expected " + std::string(what) + " (a whole number >= 0), got " + quoted_word(word.text));
    if (ec == std::errc::result_out_of_range || value > max)
        throw_at(source, word.line, word.column,
                 "expected " + std::string(what) + " of at most " + std::to_string(max) + ", got " +
                     quoted_word(word.text));
    return value;
}

}  // namespace orb::scn
