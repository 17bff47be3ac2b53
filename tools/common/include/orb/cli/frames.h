// Frame numbers for animations: the lists users type (--frames 1-240,
// 1-240x2, 1,5,9-12) and output names with a frame number in them, printf's
// %04d or Blender's #### (a run of N '#' is the number zero-padded to N).
#pragma once

#include <string>
#include <vector>

namespace orb::cli {

// The largest frame number and the most frames one list may name.
inline constexpr long kMaxFrameNumber = 999999999;
inline constexpr std::size_t kMaxFrames = 1000000;

// "12", "1-240", "1-240x2" (every second frame), and comma-separated lists
// of those ("1,5,9-12"), in the order given, duplicates dropped. Throws
// UsageError naming `option` and the bad entry.
std::vector<long> parse_frame_list(const std::string& spec, const std::string& option);

// True if `pattern` holds exactly one frame number (%d, %0Nd or a run of
// '#'); %% is a literal '%'.
bool has_frame_number(const std::string& pattern);

// `pattern` with its frame number replaced by `frame`. Throws UsageError
// unless the pattern has exactly one.
std::string expand_frame_pattern(const std::string& pattern, long frame);

}  // namespace orb::cli
