// The film: per-pixel sums over samples plus which samples it holds. Keeping
// sums (not means) makes passes, resumed runs, devices and sample slices
// rendered on other machines merge by addition, and keeping them as
// integers (film_sums.h) makes that addition exact: the same bits in any
// grouping (docs/design/exact-film-sums.md).
//
// Its channels are the rows of the one channel table, ORB_FILM_CHANNELS in
// libtables/include/orb/tables/film_channels.h (what each holds, how it is
// cleared, accumulated, merged and stored): one member per row, of the
// row's name (radiance, alpha, direct, ..., depth, object_id): a Sum
// channel's a std::vector<film::Sum> in the units of its `units` column, a
// CentreRay channel's a std::vector<float>.
//
// Plain data (libfilm): what librender renders into and libexr stores, with
// no OpenCL and no file format, so that neither depends on the other.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "orb/film/film_sums.h"
#include "orb/film/sample_ranges.h"
#include "orb/tables/film_channels.h"

namespace orb {

struct Film {
    int width = 0;
    int height = 0;
    std::uint64_t samples_per_pixel = 0;  // every pixel holds the same count
    // The sample indices the sums hold, sample_ranges.total() of them. Empty
    // while samples_per_pixel is 0; a film made by hand that sets only the
    // count holds the first samples_per_pixel indices (see held_ranges()).
    SampleRanges sample_ranges;

    // Row-major, top row first; `components` entries per pixel.
#define ORB_FILM_MEMBER_TYPE_Sum std::vector<film::Sum>
#define ORB_FILM_MEMBER_TYPE_CentreRay std::vector<float>
#define ORB_FILM_MEMBER(name, components, clear, accumulate, ...) ORB_FILM_MEMBER_TYPE_##accumulate name;
    ORB_FILM_CHANNELS(ORB_FILM_MEMBER)
#undef ORB_FILM_MEMBER
#undef ORB_FILM_MEMBER_TYPE_Sum
#undef ORB_FILM_MEMBER_TYPE_CentreRay

    // A Sum channel's sums; std::logic_error for a CentreRay channel.
    std::vector<film::Sum>& sums(film::Channel channel);
    const std::vector<film::Sum>& sums(film::Channel channel) const;
    // A CentreRay channel's values; std::logic_error for a Sum channel.
    std::vector<float>& values(film::Channel channel);
    const std::vector<float>& values(film::Channel channel) const;
    // Any channel's storage as bytes (copies to and from devices), and its
    // number of entries (0 for a channel the film does not hold).
    std::span<std::byte> bytes(film::Channel channel);
    std::span<const std::byte> bytes(film::Channel channel) const;
    std::size_t entries(film::Channel channel) const;

    // Every channel in `channels` (bits of film::channel_bit) at its clear
    // value, the others empty; no samples. A film read back from a renderer
    // holds only the channels it computes (RenderConfig::film_channels): a
    // 1920x1080 beauty film is 66 MB instead of 431 MB, and nothing is
    // written, frame after frame, into channels no one reads.
    void resize(int w, int h, std::uint32_t channels = film::kAllChannels);
    std::size_t pixel_count() const { return static_cast<std::size_t>(width) * height; }

    // sample_ranges, or [0, samples_per_pixel) when only the count was set.
    SampleRanges held_ranges() const;

    // Adds a film of other samples (same size): each channel by its merge
    // rule (sums add, exactly, saturating as film::add_sums; a Same channel
    // keeps the value of the film holding the lowest sample index). Throws
    // std::invalid_argument for another size, for sample ranges that overlap
    // (their samples would count twice) or for more than
    // film::kMaxSamplesPerPixel samples in all. Only the channels in
    // `channels` (bits of film::channel_bit) are combined; the others are
    // left as they are and not looked at in `other`, which is their
    // combination when both films hold them at their clear values (channels
    // that a render did not compute).
    void accumulate(const Film& other, std::uint32_t channels = film::kAllChannels);
};

namespace film {

// A Fixed channel whose sums reached the film's range (kSumRangeEnd units,
// 2^38 in value): those pixels may hold a clamped sample or a saturated sum,
// so their values are not the mean of their samples.
struct OutOfRange {
    Channel channel;
    std::size_t pixels = 0;       // how many pixels
    std::size_t first_pixel = 0;  // the first of them, row-major
};

// Every such channel of `film` (empty when every sum is in range).
std::vector<OutOfRange> sums_out_of_range(const Film& film);

// One line for a warning: "the radiance sums of 3 pixels (the first at (10,
// 4)) reached the film's range, 2^38: ...".
std::string describe(const OutOfRange& out, int width);

}  // namespace film

}  // namespace orb
