// Writes a film as a scanline OpenEXR without compression or with ZIP/ZIPS,
// its blocks filled (means from sums), packed and compressed on every core at
// once, then handed to OpenEXR's core library in order, which writes the
// header and the offset table. OpenEXR's C++ writer compresses blocks on its
// thread pool too, but fills them on one thread and with zlib; this is the
// path a frame loop spends its writer time in (docs/performance.md,
// "Animations and batches"; docs/design/default-layers-and-storage.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "exr_header_attributes.h"
#include "film_channels.h"
#include "orb/exr/film_exr.h"

namespace orb::exr::detail {

// Memory kept from one file to the next (one per writer thread).
struct ScanlineBuffers {
    std::vector<std::vector<std::uint8_t>> blocks;  // each block's bytes as stored
};

// `compression` is None, Zips or Zip. `planes` as plane_layout made them for `set`:
// `filled` says whether their values are set already (else each block fills
// its rows; planes after plane_layout's, a post layer's, must be filled);
// `half` stores the planes not marked always_float as HALF; exact-sum planes
// are UINT. The file goes to
// `bytes` (grown as needed), its length to `size`.
void write_scanline_exr(const Film& film, const PlaneSet& set, const std::vector<Plane>& planes,
                        bool filled, bool half, ExrCompression compression, const std::vector<HeaderAttribute>& attributes,
                        ScanlineBuffers& buffers, std::string& bytes, std::size_t& size);

// Whether write_scanline_exr writes this compression.
bool scanline_writer_handles(ExrCompression compression);

}  // namespace orb::exr::detail
