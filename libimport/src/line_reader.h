// Private: lines of a text file or of bytes in memory, with the byte offset
// and number of each, for the molecular readers: a trajectory is scanned
// once for the offsets of its frames (skipping lines without parsing them)
// and each frame read later from its offset.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace orb::molecular {

class LineReader {
public:
    // Lines of `bytes` (which must outlive the reader); `first_line` numbers the first one.
    LineReader(std::string_view bytes, std::uint64_t first_line = 1, std::uint64_t first_offset = 0);
    // Lines of the file at `path`, read in blocks. Throws InputError when it cannot be opened.
    explicit LineReader(const std::string& path);
    ~LineReader();
    LineReader(const LineReader&) = delete;
    LineReader& operator=(const LineReader&) = delete;

    // The next line without its end (LF or CR LF); false at the end of the input.
    // The view lasts until the next call.
    bool next(std::string_view& line);
    // Skips `count` lines; returns how many there were (fewer at the end of the input).
    std::uint64_t skip(std::uint64_t count);
    // Whether only blank lines (spaces, tabs, CR, LF) are left; reads them.
    bool only_blank_left();

    std::uint64_t line_number() const { return line_; }     // of the last line returned (0 before the first)
    std::uint64_t next_offset() const { return offset_; }   // byte offset of the next line's start

private:
    bool fill();  // file mode: more bytes into the buffer; false at the end of the file

    std::string_view bytes_;  // memory mode: everything; file mode: the buffer's unread part
    std::FILE* file_ = nullptr;
    std::vector<char> buffer_;
    bool at_end_ = false;
    std::uint64_t line_ = 0;
    std::uint64_t offset_ = 0;
};

// The next line that is not blank; false at the end of the input.
bool next_nonblank(LineReader& lines, std::string_view& line);

// The bytes [begin, end) of a file (end = 0: to its end). Throws InputError.
std::string read_file_range(const std::string& path, std::uint64_t begin, std::uint64_t end);
// Up to `count` bytes from the start of the file (all of a shorter one).
std::string read_file_head(const std::string& path, std::size_t count);

// White-space separated fields of a line.
std::vector<std::string_view> split_fields(std::string_view line);
void split_fields(std::string_view line, std::vector<std::string_view>& fields);  // reuses `fields`

// Whole text of a number: a double / a whole number, or false.
bool parse_double(std::string_view text, double& value);
bool parse_long(std::string_view text, long long& value);

// A per-atom value as properties keep it (a 32-bit float); throws InputError
// naming the line and the column when the number does not fit one.
float property_value(double value, const std::string& source, std::uint64_t line, std::string_view column);

// "file:line: message"
[[noreturn]] void fail_at(const std::string& source, std::uint64_t line, const std::string& message);

// `text` quoted and cut to a readable length for messages.
std::string quoted_excerpt(std::string_view text);

}  // namespace orb::molecular
