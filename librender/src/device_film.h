// The film's sums in device buffers, one buffer per channel set.
#pragma once

#include <array>
#include <cstdint>

#include "opencl.h"
#include "orb/render/film.h"

namespace orb::render {

class DeviceFilm {
public:
    DeviceFilm(const cl::Context& context, int width, int height);

    // Zero sums, depth = +inf, id = -1.
    void clear(cl::CommandQueue& queue);
    // Copies the sums back; samples_per_pixel is the caller's to fill in.
    Film read(cl::CommandQueue& queue) const;
    // Uploads `film`, which must match this size (std::invalid_argument otherwise).
    void write(cl::CommandQueue& queue, const Film& film);

    // In kernel argument order: radiance, radiance_sq, direct, indirect,
    // emission, albedo, normal, alpha, depth, object_id.
    static constexpr int kBufferCount = 10;
    const std::array<cl::Buffer, kBufferCount>& buffers() const { return buffers_; }

    std::uint64_t bytes() const;

private:
    int width_;
    int height_;
    std::array<cl::Buffer, kBufferCount> buffers_;
};

}  // namespace orb::render
