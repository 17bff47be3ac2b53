// The film's sums in device buffers: one buffer per row of the channel table
// (ORB_FILM_CHANNELS), in its order, which is render_pass's film arguments':
// 64-bit integer sums for a Sum channel, floats for a CentreRay channel
// (kernels/film.cl).
// Only the channels the kernels compute (RenderConfig::film_channels) have
// buffers of the film's size and travel between host and device; on the
// host the others are empty (Film::resize with the channel mask).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "film_arrival.h"
#include "opencl.h"
#include "orb/film/film.h"

namespace orb::render {

class DeviceFilm {
public:
    // `channels`: the bits (film::channel_bit) of the channels the kernels
    // compute. The others get a placeholder of one pixel: render_pass takes
    // an argument for every channel but never touches one it does not build.
    DeviceFilm(const cl::Context& context, int width, int height, std::uint32_t channels = film::kAllChannels);

    // Every channel at its clear value (enqueued; the queue orders it before later passes).
    void clear(cl::CommandQueue& queue);
    // Copies the computed channels' sums back into `film`, whose other
    // channels are empty, reusing its memory when it has this shape already
    // (a frame loop then touches no fresh pages); the sample count and
    // ranges are the caller's to fill in.
    void read(cl::CommandQueue& queue, Film& film) const;
    // The same without stopping the device: on `queue` (after the passes
    // enqueued before, before any clear or pass enqueued after) the computed
    // channels are copied into staging buffers on the device, which
    // `transfer` then sends into pinned host memory while `queue` goes on
    // (film_arrival.h).
    FilmArrival read_later(cl::CommandQueue& queue, cl::CommandQueue& transfer);
    // Uploads `film`'s computed channels, which must match this size
    // (std::invalid_argument otherwise); its other channels are not read.
    void write(cl::CommandQueue& queue, const Film& film);

    static constexpr int kBufferCount = film::kChannelCount;

    // The bytes of each buffer a film of this size computing `channels`
    // allocates (before any read_later, which adds copies of the computed
    // ones), for checking that it fits before allocating it.
    static std::vector<std::uint64_t> buffer_bytes(int width, int height, std::uint32_t channels);
    const std::array<cl::Buffer, kBufferCount>& buffers() const { return buffers_; }

    bool computes(film::Channel channel) const { return (channels_ & film::channel_bit(channel)) != 0; }

    std::uint64_t bytes() const;

private:
    std::size_t bytes_in(const film::ChannelInfo& info) const;      // of the whole film
    std::size_t buffer_bytes(const film::ChannelInfo& info) const;  // of its buffer: the film's or a placeholder's
    bool has_this_shape(const Film& film) const;
    void enqueue_reads(cl::CommandQueue& queue, Film& film) const;  // the computed channels, into `film`
    void check_shape(const Film& film) const;  // for write(): size and computed channels

    int width_;
    int height_;
    std::uint32_t channels_;
    std::array<cl::Buffer, kBufferCount> buffers_;
    std::array<cl::Buffer, kBufferCount> staging_;  // read_later's copies (computed channels), made on first use
    std::vector<cl::Event> staging_reads_;          // the last reads out of them
    std::shared_ptr<PinnedPool> pinned_;            // where those reads land, made on first use
};

}  // namespace orb::render
