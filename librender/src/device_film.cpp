#include "device_film.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace orb::render {

std::size_t DeviceFilm::bytes_in(const film::ChannelInfo& info) const
{
    return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * film::pixel_bytes(info);
}

std::size_t DeviceFilm::buffer_bytes(const film::ChannelInfo& info) const
{
    return computes(info.channel) ? bytes_in(info) : film::pixel_bytes(info);
}

std::vector<std::uint64_t> DeviceFilm::buffer_bytes(int width, int height, std::uint32_t channels)
{
    std::vector<std::uint64_t> bytes;
    const auto pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
    for (const film::ChannelInfo& info : film::kChannels)
        bytes.push_back(((channels & film::channel_bit(info.channel)) != 0 ? pixels : 1) * film::pixel_bytes(info));
    return bytes;
}

DeviceFilm::DeviceFilm(const cl::Context& context, int width, int height, std::uint32_t channels)
    : width_(width), height_(height), channels_(channels & film::kAllChannels)
{
    for (const film::ChannelInfo& info : film::kChannels)
        buffers_[static_cast<int>(info.channel)] =
            cl::Buffer(context, CL_MEM_READ_WRITE, buffer_bytes(info));
}

void DeviceFilm::clear(cl::CommandQueue& queue)
{
    // Placeholders too (a few bytes): a pass an observer captures (pass_observer.h; dev/pass_capture) then
    // holds no uninitialised memory.
    for (const film::ChannelInfo& info : film::kChannels) {
        const cl::Buffer& buffer = buffers_[static_cast<int>(info.channel)];
        if (info.accumulation == film::Accumulation::Sum)
            queue.enqueueFillBuffer(buffer, film::Sum{0}, 0, buffer_bytes(info));
        else
            queue.enqueueFillBuffer(buffer, info.clear, 0, buffer_bytes(info));
    }
}

bool DeviceFilm::has_this_shape(const Film& film) const
{
    if (film.width != width_ || film.height != height_) return false;
    for (const film::ChannelInfo& info : film::kChannels)
        if (film.bytes(info.channel).size() != (computes(info.channel) ? bytes_in(info) : 0)) return false;
    return true;
}

void DeviceFilm::read(cl::CommandQueue& queue, Film& film) const
{
    // The computed channels only; a film of another shape is made anew.
    if (!has_this_shape(film)) film.resize(width_, height_, channels_);
    enqueue_reads(queue, film);
    queue.finish();
}

FilmArrival DeviceFilm::read_later(cl::CommandQueue& queue, cl::CommandQueue& transfer)
{
    // The staging buffers are read by the last read_later's transfers: those
    // end long before a frame later, but must have ended.
    if (!staging_reads_.empty()) cl::Event::waitForEvents(staging_reads_);
    staging_reads_.clear();
    const cl::Context context = queue.getInfo<CL_QUEUE_CONTEXT>();
    if (!pinned_) {
        std::array<std::size_t, film::kChannelCount> bytes{};
        for (const film::ChannelInfo& info : film::kChannels)
            if (computes(info.channel)) bytes[static_cast<int>(info.channel)] = bytes_in(info);
        pinned_ = std::make_shared<PinnedPool>(context, bytes);
    }
    std::shared_ptr<PinnedChannels> landing = pinned_->take(transfer);
    for (const film::ChannelInfo& info : film::kChannels) {
        if (!computes(info.channel)) continue;
        const int index = static_cast<int>(info.channel);
        const std::size_t bytes = bytes_in(info);
        if (!staging_[index]()) staging_[index] = cl::Buffer(context, CL_MEM_READ_WRITE, bytes);
        cl::Event copied;
        queue.enqueueCopyBuffer(buffers_[index], staging_[index], 0, 0, bytes, nullptr, &copied);
        const std::vector<cl::Event> after{copied};
        cl::Event read;
        transfer.enqueueReadBuffer(staging_[index], CL_FALSE, 0, bytes, landing->mapped[index], &after, &read);
        staging_reads_.push_back(read);
    }
    // Both queues start now (a queue may hold its commands back until flushed).
    queue.flush();
    transfer.flush();
    return FilmArrival(staging_reads_, std::move(landing), width_, height_, channels_);
}

void DeviceFilm::enqueue_reads(cl::CommandQueue& queue, Film& film) const
{
    for (const film::ChannelInfo& info : film::kChannels) {
        if (!computes(info.channel)) continue;
        const std::span<std::byte> into = film.bytes(info.channel);
        queue.enqueueReadBuffer(buffers_[static_cast<int>(info.channel)], CL_FALSE, 0, into.size(), into.data());
    }
}

void DeviceFilm::check_shape(const Film& film) const
{
    if (film.width != width_ || film.height != height_)
        throw std::invalid_argument("the film is " + std::to_string(film.width) + "x" + std::to_string(film.height) +
                                    " but the renderer renders " + std::to_string(width_) + "x" +
                                    std::to_string(height_));
    for (const film::ChannelInfo& info : film::kChannels)
        if (computes(info.channel) && film.bytes(info.channel).size() != bytes_in(info))
            throw std::invalid_argument(std::string("film channel '") + info.name + "' has " +
                                        std::to_string(film.entries(info.channel)) + " entries, expected " +
                                        std::to_string(bytes_in(info) / film::entry_bytes(info)));
}

void DeviceFilm::write(cl::CommandQueue& queue, const Film& film)
{
    check_shape(film);
    for (const film::ChannelInfo& info : film::kChannels) {
        if (!computes(info.channel)) continue;
        const std::span<const std::byte> from = film.bytes(info.channel);
        queue.enqueueWriteBuffer(buffers_[static_cast<int>(info.channel)], CL_FALSE, 0, from.size(), from.data());
    }
    queue.finish();
}

std::uint64_t DeviceFilm::bytes() const
{
    std::uint64_t total = 0;
    for (const film::ChannelInfo& info : film::kChannels) {
        total += buffer_bytes(info);
        if (staging_[static_cast<int>(info.channel)]()) total += bytes_in(info);
    }
    return total;
}

}  // namespace orb::render
