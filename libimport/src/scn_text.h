// Lexical layer of the .scn reader: the text split into lines and
// whitespace-separated words, each word knowing its line and column, plus the
// number conversions the grammar needs. Every failure names file:line:column.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace orb::scn {

struct Word {
    std::string_view text;
    int line = 0;
    int column = 0;  // 1-based byte column
};

// One physical line: its words and where the line ends (for "got end of line").
struct Line {
    int number = 0;
    int end_column = 1;  // column just past the last non-whitespace byte
    std::vector<Word> words;
};

// Rejects anything that is not plain ASCII text (NUL bytes, control codes,
// bytes >= 0x80) with the position of the first offending byte. A leading
// UTF-8 byte-order mark is tolerated and skipped; the returned view is the
// text without it.
std::string_view require_text(std::string_view bytes, const std::string& source);

// Walks the text line by line, skipping lines that hold only whitespace.
// Lines end at '\n'; '\r', '\t', '\v', '\f' and ' ' separate words.
class LineReader {
public:
    LineReader(std::string_view text, int first_column_offset);
    bool next(Line& line);           // false at end of input
    // Where the input ends, for "got end of file" messages.
    int end_line() const { return end_line_; }
    int end_column() const { return end_column_; }

private:
    std::string_view text_;
    size_t position_ = 0;
    int line_number_ = 0;
    int first_column_offset_;  // bytes of a skipped byte-order mark, counted on line 1
    int end_line_ = 1;
    int end_column_ = 1;
};

// A finite double in C strtod's decimal syntax ("1e5", "+2", ".75", "-0.5E-3").
// Hexadecimal, "inf", "nan" and values that overflow are errors; values that
// underflow read as strtod reads them (zero or a subnormal).
double parse_number(const Word& word, const std::string& source, std::string_view what);

// A whole number in decimal digits (optional leading '+'), at most `max`.
std::uint64_t parse_count(const Word& word, const std::string& source, std::string_view what,
                          std::uint64_t max);

// "'abc'" for messages, shortened and kept printable.
std::string quoted_word(std::string_view text);

}  // namespace orb::scn
