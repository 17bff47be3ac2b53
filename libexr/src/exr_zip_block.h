// OpenEXR's ZIP (16 scanlines a block) and ZIPS (one) compression of one
// block of pixel bytes, as the OpenEXR file format defines it: the bytes
// split into those at even and at odd positions (for little-endian values
// that gathers high and low bytes apart), each byte then replaced by its
// difference from the previous one plus 128, and the result deflated in
// zlib's format (RFC 1950). Compressed with libdeflate, which takes about
// half zlib's time at the same ratio on rendered float data (the figures are
// in docs/design/default-layers-and-storage.md); any OpenEXR reader reads the result.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

struct libdeflate_compressor;

namespace orb::exr::detail {

class ZipBlockCompressor {
public:
    ZipBlockCompressor();
    ~ZipBlockCompressor();
    ZipBlockCompressor(const ZipBlockCompressor&) = delete;
    ZipBlockCompressor& operator=(const ZipBlockCompressor&) = delete;

    // The compressed block in `out`. Returns false, leaving `out`
    // unspecified, when it would be no smaller than `raw`: OpenEXR then
    // stores the block's bytes as they are.
    bool compress(std::span<const std::uint8_t> raw, std::vector<std::uint8_t>& out);

private:
    libdeflate_compressor* compressor_;
    std::vector<std::uint8_t> predicted_;
};

}  // namespace orb::exr::detail
