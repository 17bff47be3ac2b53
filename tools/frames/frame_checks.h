// orb-frames --missing: which frames of a pattern still need rendering.
#pragma once

#include <optional>
#include <string>

namespace orb::frames {

// What a finished frame must also match, when asked (a re-run with another
// --spp or size must not keep frames of the old one).
struct FrameRequirements {
    std::optional<unsigned long long> spp;
    std::optional<std::string> samples;  // exactly these sample indices, "START:COUNT" (a slice)
    std::optional<int> width, height;
};

// Empty when `path` is a complete orb-render EXR meeting `wanted`, else why not.
std::string why_not_done(const std::string& path, const FrameRequirements& wanted);

}  // namespace orb::frames
