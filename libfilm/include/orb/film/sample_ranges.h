// Which sample indices a film holds. The RNG is counter-based, so a sample
// is a pure function of (pixel, sample index, seed): films holding disjoint
// sets of indices add up to the film of their union, whichever machine,
// device, pass or run rendered them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace orb {

// The samples [first, first + count).
struct SampleRange {
    std::uint64_t first = 0;
    std::uint64_t count = 0;
    std::uint64_t end() const { return first + count; }
    bool operator==(const SampleRange&) const = default;
};

// A set of sample indices as sorted, disjoint ranges; touching ranges are
// joined, so a set has one spelling ("0:16,32:8").
class SampleRanges {
public:
    SampleRanges() = default;
    explicit SampleRanges(SampleRange range) { add(range); }

    // Adds `range` (an empty one is ignored). Throws std::invalid_argument if
    // it shares an index with the set or runs past 2^64 - 1.
    void add(SampleRange range);
    // Adds every range of `other`; throws like add() (and then adds nothing).
    void add(const SampleRanges& other);

    bool overlaps(SampleRange range) const;
    bool overlaps(const SampleRanges& other) const;
    bool empty() const { return ranges_.empty(); }
    std::uint64_t total() const;  // how many indices
    std::uint64_t first() const;  // the lowest index; 0 when empty
    std::uint64_t end() const;    // one past the highest index; 0 when empty
    const std::vector<SampleRange>& ranges() const { return ranges_; }

    // "START:COUNT[,START:COUNT...]", "" when empty.
    std::string format() const;
    // Reads format()'s spelling (ranges in any order, not overlapping, counts
    // of at least 1). Throws std::invalid_argument saying what is wrong.
    static SampleRanges parse(const std::string& text);

    bool operator==(const SampleRanges&) const = default;

private:
    std::vector<SampleRange> ranges_;
};

// One "START:COUNT" (COUNT >= 1). Throws std::invalid_argument.
SampleRange parse_sample_range(const std::string& text);

}  // namespace orb
