#include "line_reader.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>

#include "orb/scene/error.h"

namespace orb::molecular {
namespace {

constexpr std::size_t kBlockBytes = std::size_t{1} << 20;

}  // namespace

LineReader::LineReader(std::string_view bytes, std::uint64_t first_line, std::uint64_t first_offset)
    : bytes_(bytes), at_end_(true), line_(first_line - 1), offset_(first_offset) {}

LineReader::LineReader(const std::string& path) {
    file_ = std::fopen(path.c_str(), "rb");
    if (!file_) throw InputError(path + ": cannot read: " + std::strerror(errno));
    buffer_.resize(kBlockBytes);
}

LineReader::~LineReader() {
    if (file_) std::fclose(file_);
}

bool LineReader::fill() {
    if (at_end_) return false;
    // Keep the unread part at the front, and grow for a line longer than the buffer.
    const std::size_t kept = bytes_.size();
    if (kept > 0 && bytes_.data() != buffer_.data()) std::memmove(buffer_.data(), bytes_.data(), kept);
    if (buffer_.size() - kept < kBlockBytes / 2) buffer_.resize(buffer_.size() * 2);
    const std::size_t got = std::fread(buffer_.data() + kept, 1, buffer_.size() - kept, file_);
    if (got == 0) {
        if (std::ferror(file_)) throw InputError("read error: " + std::string(std::strerror(errno)));
        at_end_ = true;
    }
    bytes_ = std::string_view(buffer_.data(), kept + got);
    return got > 0;
}

bool LineReader::next(std::string_view& line) {
    std::size_t searched = 0;
    for (;;) {
        const void* found = std::memchr(bytes_.data() + searched, '\n', bytes_.size() - searched);
        if (found) {
            const std::size_t end = static_cast<std::size_t>(static_cast<const char*>(found) - bytes_.data());
            line = bytes_.substr(0, end);
            bytes_.remove_prefix(end + 1);
            offset_ += end + 1;
            break;
        }
        searched = bytes_.size();
        if (!fill()) {
            if (bytes_.empty()) return false;
            line = bytes_;  // the last line, without an end
            offset_ += bytes_.size();
            bytes_ = {};
            break;
        }
    }
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++line_;
    return true;
}

std::uint64_t LineReader::skip(std::uint64_t count) {
    std::uint64_t skipped = 0;
    while (skipped < count) {
        const void* found = std::memchr(bytes_.data(), '\n', bytes_.size());
        if (found) {
            const std::size_t end = static_cast<std::size_t>(static_cast<const char*>(found) - bytes_.data());
            bytes_.remove_prefix(end + 1);
            offset_ += end + 1;
            ++skipped;
            ++line_;
            continue;
        }
        if (!fill()) {
            if (!bytes_.empty()) {  // a last line without an end
                offset_ += bytes_.size();
                bytes_ = {};
                ++skipped;
                ++line_;
            }
            break;
        }
    }
    return skipped;
}

bool LineReader::only_blank_left() {
    std::string_view line;
    while (next(line))
        if (line.find_first_not_of(" \t\r") != std::string_view::npos) return false;
    return true;
}

bool next_nonblank(LineReader& lines, std::string_view& line) {
    while (lines.next(line))
        if (line.find_first_not_of(" \t\r") != std::string_view::npos) return true;
    return false;
}

std::string read_file_range(const std::string& path, std::uint64_t begin, std::uint64_t end) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) throw InputError(path + ": cannot read: " + std::strerror(errno));
    std::string bytes;
    bool ok = fseeko(file, static_cast<off_t>(begin), SEEK_SET) == 0;
    if (ok && end > begin) {
        bytes.resize(end - begin);
        ok = std::fread(bytes.data(), 1, bytes.size(), file) == bytes.size();
    } else if (ok) {
        char block[65536];
        std::size_t got;
        while ((got = std::fread(block, 1, sizeof block, file)) > 0) bytes.append(block, got);
        ok = !std::ferror(file);
    }
    std::fclose(file);
    if (!ok) throw InputError(path + ": cannot read bytes " + std::to_string(begin) + ".. (the file changed since it was scanned?)");
    return bytes;
}

std::string read_file_head(const std::string& path, std::size_t count) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) throw InputError(path + ": cannot read: " + std::strerror(errno));
    std::string head(count, '\0');
    head.resize(std::fread(head.data(), 1, head.size(), file));
    const bool failed = std::ferror(file);
    std::fclose(file);
    if (failed) throw InputError(path + ": cannot read: " + std::strerror(errno));
    return head;
}

void split_fields(std::string_view line, std::vector<std::string_view>& fields) {
    fields.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) fields.push_back(line.substr(start, i - start));
    }
}

std::vector<std::string_view> split_fields(std::string_view line) {
    std::vector<std::string_view> fields;
    split_fields(line, fields);
    return fields;
}

bool parse_double(std::string_view text, double& value) {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc() && end == text.data() + text.size()) return std::isfinite(value);
    // Fortran writes exponents with D (1.0D+02).
    if (ec == std::errc() && end < text.data() + text.size() && (*end == 'd' || *end == 'D')) {
        std::string copy(text);
        copy[static_cast<std::size_t>(end - text.data())] = 'e';
        return parse_double(copy, value);
    }
    return false;
}

bool parse_long(std::string_view text, long long& value) {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size() && !text.empty();
}

float property_value(double value, const std::string& source, std::uint64_t line, std::string_view column) {
    const float narrowed = static_cast<float>(value);
    if (!std::isfinite(narrowed))
    {
        char text[32];
        std::snprintf(text, sizeof text, "%.6g", value);
        fail_at(source, line, "column " + quoted_excerpt(column) + ": " + text + " does not fit a 32-bit float (about 3.4e38 at most)");
    }
    return narrowed;
}

void fail_at(const std::string& source, std::uint64_t line, const std::string& message) {
    throw InputError(source + ":" + std::to_string(line) + ": " + message);
}

std::string quoted_excerpt(std::string_view text) {
    constexpr std::size_t kShown = 60;
    std::string shown(text.substr(0, kShown));
    for (char& c : shown)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    return "'" + shown + (text.size() > kShown ? "...'" : "'");
}

}  // namespace orb::molecular
