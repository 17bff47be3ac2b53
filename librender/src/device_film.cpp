#include "device_film.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace orb::render {
namespace {

constexpr int kColourSets = 7;  // the first seven buffers hold 3 floats per pixel

size_t floats_in(int buffer, size_t pixels) { return buffer < kColourSets ? pixels * 3 : pixels; }

// The Film members in the order of DeviceFilm::buffers().
std::array<std::vector<float>*, DeviceFilm::kBufferCount> film_sets(Film& film)
{
    return {&film.radiance, &film.radiance_sq, &film.direct,   &film.indirect, &film.emission,
            &film.albedo,   &film.normal,      &film.alpha,    &film.depth,    &film.object_id};
}

}  // namespace

DeviceFilm::DeviceFilm(const cl::Context& context, int width, int height) : width_(width), height_(height)
{
    const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
    for (int i = 0; i < kBufferCount; ++i)
        buffers_[i] = cl::Buffer(context, CL_MEM_READ_WRITE, floats_in(i, pixels) * sizeof(float));
}

void DeviceFilm::clear(cl::CommandQueue& queue)
{
    const size_t pixels = static_cast<size_t>(width_) * static_cast<size_t>(height_);
    for (int i = 0; i < kBufferCount; ++i) {
        float value = 0.0f;
        if (i == 8) value = std::numeric_limits<float>::infinity();
        if (i == 9) value = -1.0f;
        queue.enqueueFillBuffer(buffers_[i], value, 0, floats_in(i, pixels) * sizeof(float));
    }
    queue.finish();
}

Film DeviceFilm::read(cl::CommandQueue& queue) const
{
    Film film;
    film.resize(width_, height_);
    auto sets = film_sets(film);
    for (int i = 0; i < kBufferCount; ++i)
        queue.enqueueReadBuffer(buffers_[i], CL_FALSE, 0, sets[i]->size() * sizeof(float), sets[i]->data());
    queue.finish();
    return film;
}

void DeviceFilm::write(cl::CommandQueue& queue, const Film& film)
{
    if (film.width != width_ || film.height != height_)
        throw std::invalid_argument("the film is " + std::to_string(film.width) + "x" + std::to_string(film.height) +
                                    " but the renderer renders " + std::to_string(width_) + "x" +
                                    std::to_string(height_));
    Film copy = film;  // film_sets() needs non-const access; buffers are small next to a render
    auto sets = film_sets(copy);
    const size_t pixels = static_cast<size_t>(width_) * static_cast<size_t>(height_);
    static const char* const names[kBufferCount] = {"radiance", "radiance_sq", "direct", "indirect", "emission",
                                                    "albedo",   "normal",      "alpha",  "depth",    "object_id"};
    for (int i = 0; i < kBufferCount; ++i)
        if (sets[i]->size() != floats_in(i, pixels))
            throw std::invalid_argument(std::string("film channel set '") + names[i] + "' has " +
                                        std::to_string(sets[i]->size()) + " floats, expected " +
                                        std::to_string(floats_in(i, pixels)));
    for (int i = 0; i < kBufferCount; ++i)
        queue.enqueueWriteBuffer(buffers_[i], CL_FALSE, 0, sets[i]->size() * sizeof(float), sets[i]->data());
    queue.finish();
}

std::uint64_t DeviceFilm::bytes() const
{
    const size_t pixels = static_cast<size_t>(width_) * static_cast<size_t>(height_);
    std::uint64_t total = 0;
    for (int i = 0; i < kBufferCount; ++i) total += floats_in(i, pixels) * sizeof(float);
    return total;
}

}  // namespace orb::render
