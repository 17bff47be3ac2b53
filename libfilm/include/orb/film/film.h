// The film: per-pixel sums over samples plus which samples it holds. Keeping
// sums (not means) makes passes, resumed runs, devices and sample slices
// rendered on other machines merge exactly by addition.
//
// Its channels are the rows of the one channel table, ORB_FILM_CHANNELS in
// kernels/include/orb/kernels/film_channels.h (what each holds, how it is
// cleared, accumulated, merged and stored): one std::vector<float> member per
// row, of the row's name (radiance, alpha, direct, ..., depth, object_id).
//
// Plain data (libfilm): what librender renders into and libexr stores, with
// no OpenCL and no file format, so that neither depends on the other.
#pragma once

#include <cstdint>
#include <vector>

#include "orb/kernels/film_channels.h"
#include "orb/film/sample_ranges.h"

namespace orb {

struct Film {
    int width = 0;
    int height = 0;
    std::uint64_t samples_per_pixel = 0;  // every pixel holds the same count
    // The sample indices the sums hold, sample_ranges.total() of them. Empty
    // while samples_per_pixel is 0; a film made by hand that sets only the
    // count holds the first samples_per_pixel indices (see held_ranges()).
    SampleRanges sample_ranges;

    // Row-major, top row first; `components` floats per pixel.
#define ORB_FILM_MEMBER(name, ...) std::vector<float> name;
    ORB_FILM_CHANNELS(ORB_FILM_MEMBER)
#undef ORB_FILM_MEMBER

    std::vector<float>& channel(film::Channel channel);
    const std::vector<float>& channel(film::Channel channel) const;

    // Every channel in `channels` (bits of film::channel_bit) at its clear
    // value, the others empty; no samples. A film read back from a renderer
    // holds only the channels it computes (RenderConfig::film_channels): a
    // 1920x1080 beauty film is 33 MB instead of 199 MB, and nothing is
    // written, frame after frame, into channels no one reads.
    void resize(int w, int h, std::uint32_t channels = film::kAllChannels);
    std::size_t pixel_count() const { return static_cast<std::size_t>(width) * height; }

    // sample_ranges, or [0, samples_per_pixel) when only the count was set.
    SampleRanges held_ranges() const;

    // Adds a film of other samples (same size): each channel by its merge
    // rule (sums add; a Same channel keeps the value of the film holding the
    // lowest sample index). Throws std::invalid_argument for another size or
    // for sample ranges that overlap (their samples would count twice).
    // Only the channels in `channels` (bits of film::channel_bit) are
    // combined; the others are left as they are and not looked at in
    // `other`, which is their combination when both films hold them at
    // their clear values (channels that a render did not compute).
    void accumulate(const Film& other, std::uint32_t channels = film::kAllChannels);
};

}  // namespace orb
