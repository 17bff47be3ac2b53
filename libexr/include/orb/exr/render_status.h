// Whether an EXR that orb-render wrote is a finished render, read from its
// header and offset table only (no pixels), so that checking a long sequence
// of large frames stays cheap (the offset table and chunk headers). Tools that skip finished work (orb-frames
// --missing, orb-farm) share this one definition of "finished".
#pragma once

#include <cstdint>
#include <string>

namespace orb::exr {

struct RenderStatus {
    bool complete = false;
    std::string reason;            // why it is not complete ("no such file", "stopped at 12 of 64 samples", ...)
    std::uint64_t spp = 0;         // orb:spp
    std::uint64_t target_spp = 0;  // orb:targetSpp
    std::string sample_ranges;     // orb:sampleRanges ("0:256", "256:256"); "0:spp" for film format 1
    int width = 0, height = 0;
};

// Complete means: a readable OpenEXR file with orb-render's orb:spp and
// orb:targetSpp attributes, orb:spp >= orb:targetSpp (an interrupted or
// time-limited render stops short of its target), and every scanline present
// (a file cut short anywhere is not complete). Never throws for a bad file; the
// reason says what is wrong.
RenderStatus inspect_render(const std::string& path);

}  // namespace orb::exr
