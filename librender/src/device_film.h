// The film's sums in device buffers: one buffer per row of the channel table
// (ORB_FILM_CHANNELS), in its order, which is render_pass's film arguments'.
#pragma once

#include <array>
#include <cstdint>

#include "opencl.h"
#include "orb/render/film.h"

namespace orb::render {

class DeviceFilm {
public:
    DeviceFilm(const cl::Context& context, int width, int height);

    // Every channel at its clear value (enqueued; the queue orders it before later passes).
    void clear(cl::CommandQueue& queue);
    // Copies the sums back; the sample count and ranges are the caller's to fill in.
    Film read(cl::CommandQueue& queue) const;
    // Uploads `film`'s channels, which must match this size (std::invalid_argument otherwise).
    void write(cl::CommandQueue& queue, const Film& film);

    static constexpr int kBufferCount = film::kChannelCount;
    const std::array<cl::Buffer, kBufferCount>& buffers() const { return buffers_; }

    std::uint64_t bytes() const;

private:
    std::size_t floats_in(const film::ChannelInfo& info) const;

    int width_;
    int height_;
    std::array<cl::Buffer, kBufferCount> buffers_;
};

}  // namespace orb::render
