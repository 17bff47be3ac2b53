#include "device_film.h"

#include <stdexcept>
#include <string>

namespace orb::render {

std::size_t DeviceFilm::floats_in(const film::ChannelInfo& info) const
{
    return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) *
           static_cast<std::size_t>(info.components);
}

DeviceFilm::DeviceFilm(const cl::Context& context, int width, int height) : width_(width), height_(height)
{
    for (const film::ChannelInfo& info : film::kChannels)
        buffers_[static_cast<int>(info.channel)] =
            cl::Buffer(context, CL_MEM_READ_WRITE, floats_in(info) * sizeof(float));
}

void DeviceFilm::clear(cl::CommandQueue& queue)
{
    for (const film::ChannelInfo& info : film::kChannels)
        queue.enqueueFillBuffer(buffers_[static_cast<int>(info.channel)], info.clear, 0,
                                floats_in(info) * sizeof(float));
}

Film DeviceFilm::read(cl::CommandQueue& queue) const
{
    Film film;
    film.resize(width_, height_);
    for (const film::ChannelInfo& info : film::kChannels) {
        std::vector<float>& values = film.channel(info.channel);
        queue.enqueueReadBuffer(buffers_[static_cast<int>(info.channel)], CL_FALSE, 0, values.size() * sizeof(float),
                                values.data());
    }
    queue.finish();
    return film;
}

void DeviceFilm::write(cl::CommandQueue& queue, const Film& film)
{
    if (film.width != width_ || film.height != height_)
        throw std::invalid_argument("the film is " + std::to_string(film.width) + "x" + std::to_string(film.height) +
                                    " but the renderer renders " + std::to_string(width_) + "x" +
                                    std::to_string(height_));
    for (const film::ChannelInfo& info : film::kChannels)
        if (film.channel(info.channel).size() != floats_in(info))
            throw std::invalid_argument(std::string("film channel '") + info.name + "' has " +
                                        std::to_string(film.channel(info.channel).size()) + " floats, expected " +
                                        std::to_string(floats_in(info)));
    for (const film::ChannelInfo& info : film::kChannels) {
        const std::vector<float>& values = film.channel(info.channel);
        queue.enqueueWriteBuffer(buffers_[static_cast<int>(info.channel)], CL_FALSE, 0, values.size() * sizeof(float),
                                 values.data());
    }
    queue.finish();
}

std::uint64_t DeviceFilm::bytes() const
{
    std::uint64_t total = 0;
    for (const film::ChannelInfo& info : film::kChannels) total += floats_in(info) * sizeof(float);
    return total;
}

}  // namespace orb::render
