// Frame lists ("1-240", "1-240x10", "1,5,9-12") and output patterns with a
// frame number ("beauty.%04d.exr", Blender's "beauty.####.exr"), shared by
// every tool that works on animation frames so they all read them alike.
// The grammar is documented in docs/frames.md.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace orb::cli {

// The largest frame number and the most frames one list may name: a list
// expands into memory, so "0-999999999" must be refused, not allocated.
inline constexpr int kMaxFrameNumber = 99'999'999;
inline constexpr std::size_t kMaxFrameCount = 1'000'000;

struct FrameSpec {
    // In the order written, each frame once (a frame repeated later is
    // dropped), so "1-240x10,1-240" renders every tenth frame first.
    std::vector<int> frames;
    // The smallest and largest frame numbers the list writes: a range's end
    // counts even when its step passes over it ("1-240x2" spans 1 ... 240),
    // so a stepped preview lies on the same timeline as the full list.
    int lowest = 0, highest = 0;

    std::size_t size() const { return frames.size(); }
    auto begin() const { return frames.begin(); }
    auto end() const { return frames.end(); }
};

// Parses a comma-separated list of items, each `N`, `A-B` (A <= B) or
// `A-BxSTEP` (STEP >= 1: A, A+STEP, ... up to B); frames are whole numbers
// 0 ... kMaxFrameNumber; spaces around items are ignored. Throws
// orb::cli::UsageError with a message that quotes the text and says what was
// expected.
FrameSpec parse_frame_spec(std::string_view text);

// How many frame-number fields `pattern` has: `%d`, `%0Nd` (N = 1 ... 9) and
// each run of `#` (Blender's: as many digits as there are #). `%%` is a
// literal %. Throws orb::cli::UsageError for any other % conversion.
int count_frame_fields(std::string_view pattern);

// `pattern` with every frame-number field replaced by `frame`, zero-padded to
// the field's width (wider numbers are written in full, as printf does).
// Throws orb::cli::UsageError if the pattern has no frame-number field or a
// bad % conversion, or if `frame` is negative.
std::string expand_frame_pattern(std::string_view pattern, int frame);

}  // namespace orb::cli
