#include "device_film.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

namespace orb::render {

std::size_t DeviceFilm::floats_in(const film::ChannelInfo& info) const
{
    return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) *
           static_cast<std::size_t>(info.components);
}

std::size_t DeviceFilm::buffer_floats(const film::ChannelInfo& info) const
{
    return computes(info.channel) ? floats_in(info) : static_cast<std::size_t>(info.components);
}

DeviceFilm::DeviceFilm(const cl::Context& context, int width, int height, std::uint32_t channels)
    : width_(width), height_(height), channels_(channels & film::kAllChannels)
{
    for (const film::ChannelInfo& info : film::kChannels)
        buffers_[static_cast<int>(info.channel)] =
            cl::Buffer(context, CL_MEM_READ_WRITE, buffer_floats(info) * sizeof(float));
}

void DeviceFilm::clear(cl::CommandQueue& queue)
{
    // Placeholders too (a few bytes): a captured pass (pass_capture.h) then
    // holds no uninitialised memory.
    for (const film::ChannelInfo& info : film::kChannels)
        queue.enqueueFillBuffer(buffers_[static_cast<int>(info.channel)], info.clear, 0,
                                buffer_floats(info) * sizeof(float));
}

bool DeviceFilm::has_this_shape(const Film& film) const
{
    if (film.width != width_ || film.height != height_) return false;
    for (const film::ChannelInfo& info : film::kChannels)
        if (film.channel(info.channel).size() != floats_in(info)) return false;
    return true;
}

void DeviceFilm::read(cl::CommandQueue& queue, Film& film) const
{
    // A film of another shape is made anew, every channel at its clear value.
    const bool reused = has_this_shape(film);
    if (!reused) film.resize(width_, height_);
    enqueue_reads(queue, film);
    // A reused film may hold an earlier frame in the channels that are not
    // read back: cleared on the host while the others travel.
    if (reused) clear_uncomputed(film);
    queue.finish();
}

void DeviceFilm::enqueue_reads(cl::CommandQueue& queue, Film& film) const
{
    for (const film::ChannelInfo& info : film::kChannels) {
        if (!computes(info.channel)) continue;
        std::vector<float>& values = film.channel(info.channel);
        queue.enqueueReadBuffer(buffers_[static_cast<int>(info.channel)], CL_FALSE, 0, values.size() * sizeof(float),
                                values.data());
    }
}

void DeviceFilm::clear_uncomputed(Film& film) const
{
    // At 1920x1080 the channels a beauty-only run leaves out are 166 MB,
    // which one core takes 15-20 ms to write (a 16-core Xeon) while an H100
    // sends the computed 33 MB in 3 ms: large channels are written each by a
    // thread of its own (memory bandwidth grows with the cores writing).
    std::vector<std::jthread> writers;
    for (const film::ChannelInfo& info : film::kChannels) {
        if (computes(info.channel)) continue;
        std::vector<float>& values = film.channel(info.channel);
        const auto write = [&values, clear = info.clear] { std::fill(values.begin(), values.end(), clear); };
        if (values.size() < kFloatsWorthAThread) {
            write();
            continue;
        }
        try {
            writers.emplace_back(write);
        } catch (const std::system_error&) {
            write();  // no thread to be had: this one writes it
        }
    }
}

void DeviceFilm::check_shape(const Film& film) const
{
    if (film.width != width_ || film.height != height_)
        throw std::invalid_argument("the film is " + std::to_string(film.width) + "x" + std::to_string(film.height) +
                                    " but the renderer renders " + std::to_string(width_) + "x" +
                                    std::to_string(height_));
    for (const film::ChannelInfo& info : film::kChannels)
        if (computes(info.channel) && film.channel(info.channel).size() != floats_in(info))
            throw std::invalid_argument(std::string("film channel '") + info.name + "' has " +
                                        std::to_string(film.channel(info.channel).size()) + " floats, expected " +
                                        std::to_string(floats_in(info)));
}

void DeviceFilm::write(cl::CommandQueue& queue, const Film& film)
{
    check_shape(film);
    for (const film::ChannelInfo& info : film::kChannels) {
        if (!computes(info.channel)) continue;
        const std::vector<float>& values = film.channel(info.channel);
        queue.enqueueWriteBuffer(buffers_[static_cast<int>(info.channel)], CL_FALSE, 0, values.size() * sizeof(float),
                                 values.data());
    }
    queue.finish();
}

std::uint64_t DeviceFilm::bytes() const
{
    std::uint64_t total = 0;
    for (const film::ChannelInfo& info : film::kChannels) total += buffer_floats(info) * sizeof(float);
    return total;
}

}  // namespace orb::render
