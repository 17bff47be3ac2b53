#include "orb/film/sample_ranges.h"

#include <algorithm>
#include <charconv>
#include <limits>
#include <stdexcept>

namespace orb {
namespace {

std::string spell(SampleRange r) { return std::to_string(r.first) + ":" + std::to_string(r.count); }

std::uint64_t parse_index(const std::string& digits, const std::string& whole) {
    std::uint64_t value = 0;
    const char* end = digits.data() + digits.size();
    const auto [stop, error] = std::from_chars(digits.data(), end, value);
    if (digits.empty() || error != std::errc{} || stop != end)
        throw std::invalid_argument("expected START:COUNT with whole numbers below 2^64, got '" + whole + "'");
    return value;
}

}  // namespace

void SampleRanges::add(SampleRange range) {
    if (range.count == 0) return;
    if (range.first > std::numeric_limits<std::uint64_t>::max() - range.count)
        throw std::invalid_argument("sample range " + spell(range) + " runs past the last sample index 2^64-1");
    if (overlaps(range)) throw std::invalid_argument("sample range " + spell(range) + " overlaps " + format());
    auto at = std::lower_bound(ranges_.begin(), ranges_.end(), range,
                               [](SampleRange a, SampleRange b) { return a.first < b.first; });
    at = ranges_.insert(at, range);
    // Join with the neighbours it touches.
    if (at + 1 != ranges_.end() && at->end() == (at + 1)->first) {
        at->count += (at + 1)->count;
        ranges_.erase(at + 1);
    }
    if (at != ranges_.begin() && (at - 1)->end() == at->first) {
        (at - 1)->count += at->count;
        ranges_.erase(at);
    }
}

void SampleRanges::add(const SampleRanges& other) {
    if (overlaps(other))
        throw std::invalid_argument("sample ranges " + other.format() + " overlap " + format());
    for (SampleRange r : other.ranges_) add(r);
}

bool SampleRanges::overlaps(SampleRange range) const {
    if (range.count == 0) return false;
    return std::any_of(ranges_.begin(), ranges_.end(),
                       [&](SampleRange r) { return r.first < range.end() && range.first < r.end(); });
}

bool SampleRanges::overlaps(const SampleRanges& other) const {
    return std::any_of(other.ranges_.begin(), other.ranges_.end(), [&](SampleRange r) { return overlaps(r); });
}

std::uint64_t SampleRanges::total() const {
    std::uint64_t sum = 0;
    for (SampleRange r : ranges_) sum += r.count;
    return sum;
}

std::uint64_t SampleRanges::first() const { return ranges_.empty() ? 0 : ranges_.front().first; }
std::uint64_t SampleRanges::end() const { return ranges_.empty() ? 0 : ranges_.back().end(); }

std::string SampleRanges::format() const {
    std::string text;
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about
    // const char* + std::string&& here.
    for (SampleRange r : ranges_) {
        if (!text.empty()) text += ',';
        text += spell(r);
    }
    return text;
}

SampleRange parse_sample_range(const std::string& text) {
    const auto colon = text.find(':');
    if (colon == std::string::npos)
        throw std::invalid_argument("expected START:COUNT (first sample index and how many), got '" + text + "'");
    SampleRange range{parse_index(text.substr(0, colon), text), parse_index(text.substr(colon + 1), text)};
    if (range.count == 0) throw std::invalid_argument("a sample range needs a COUNT of at least 1, got '" + text + "'");
    if (range.first > std::numeric_limits<std::uint64_t>::max() - range.count)
        throw std::invalid_argument("sample range '" + text + "' runs past the last sample index 2^64-1");
    return range;
}

SampleRanges SampleRanges::parse(const std::string& text) {
    SampleRanges set;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t comma = text.find(',', start);
        if (comma == std::string::npos) comma = text.size();
        set.add(parse_sample_range(text.substr(start, comma - start)));
        start = comma + 1;
    }
    return set;
}

}  // namespace orb
