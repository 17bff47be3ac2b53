#include "film_arrival.h"

#include <cstring>

namespace orb::render {

PinnedChannels::PinnedChannels(const cl::Context& context, cl::CommandQueue& map_queue,
                               const std::array<std::size_t, film::kChannelCount>& bytes)
    : queue(map_queue)
{
    for (int c = 0; c < film::kChannelCount; ++c) {
        if (bytes[c] == 0) continue;
        buffers[c] = cl::Buffer(context, CL_MEM_ALLOC_HOST_PTR | CL_MEM_READ_WRITE, bytes[c]);
        mapped[c] = static_cast<std::byte*>(queue.enqueueMapBuffer(buffers[c], CL_TRUE, CL_MAP_READ | CL_MAP_WRITE, 0, bytes[c]));
    }
}

PinnedChannels::~PinnedChannels()
{
    try {
        for (int c = 0; c < film::kChannelCount; ++c)
            if (mapped[c]) queue.enqueueUnmapMemObject(buffers[c], mapped[c]);
        queue.finish();
    } catch (const cl::Error&) {
        // Going away with the context: nothing left to save.
    }
}

std::shared_ptr<PinnedChannels> PinnedPool::take(cl::CommandQueue& queue)
{
    std::unique_ptr<PinnedChannels> set;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (!free_.empty()) {
            set = std::move(free_.back());
            free_.pop_back();
        }
    }
    if (!set) set = std::make_unique<PinnedChannels>(context_, queue, bytes_);
    // Handed out with a deleter that brings it back here, for as long as the pool lives.
    std::weak_ptr<PinnedPool> pool = weak_from_this();
    return std::shared_ptr<PinnedChannels>(set.release(), [pool](PinnedChannels* released) {
        if (const std::shared_ptr<PinnedPool> alive = pool.lock())
            alive->give_back(released);
        else
            delete released;
    });
}

void PinnedPool::give_back(PinnedChannels* set)
{
    const std::lock_guard<std::mutex> lock(mutex_);
    free_.emplace_back(set);
}

FilmArrival::FilmArrival(std::vector<cl::Event> transfers, std::shared_ptr<PinnedChannels> landing, int width,
                         int height, std::uint32_t channels)
    : transfers_(std::move(transfers)), landing_(std::move(landing)), width_(width), height_(height),
      channels_(channels)
{
}

void FilmArrival::wait() noexcept
{
    if (transfers_.empty()) return;
    try {
        cl::Event::waitForEvents(transfers_);
    } catch (const cl::Error&) {
    }
    transfers_.clear();
}

void FilmArrival::wait_into(Film& film)
{
    if (!transfers_.empty()) cl::Event::waitForEvents(transfers_);
    transfers_.clear();
    bool shaped = film.width == width_ && film.height == height_;
    for (const film::ChannelInfo& info : film::kChannels) {
        const std::size_t entries = (channels_ & film::channel_bit(info.channel))
                                        ? film.pixel_count() * static_cast<std::size_t>(info.components)
                                        : 0;
        shaped = shaped && film.entries(info.channel) == entries;
    }
    if (!shaped) film.resize(width_, height_, channels_);
    for (const film::ChannelInfo& info : film::kChannels) {
        const std::byte* from = landing_->mapped[static_cast<int>(info.channel)];
        if (!from) continue;
        const std::span<std::byte> into = film.bytes(info.channel);
        std::memcpy(into.data(), from, into.size());
    }
    landing_.reset();  // back to the pool
}

}  // namespace orb::render
