// printf-style frame patterns ("beauty.%04d.exr") and --frames ranges.
#pragma once

#include <string>

namespace orb::tonemap {

struct FrameRange {
    long first = 0;
    long last = 0;
};

// "12" or "1-240". Throws orb::cli::UsageError.
FrameRange parse_frame_range(const std::string& text);

// True if the path has exactly one %d / %0Nd conversion (and maybe %% escapes).
bool is_frame_pattern(const std::string& pattern);

// Substitutes the frame number. Throws orb::cli::UsageError for bad patterns.
std::string expand_frame_pattern(const std::string& pattern, long frame);

}  // namespace orb::tonemap
