// A film on its way from a device into host memory the driver can send to
// directly (pinned: allocated by OpenCL with CL_MEM_ALLOC_HOST_PTR and kept
// mapped). A transfer into ordinary (pageable) memory is staged by the
// driver through its own pinned buffer on the calling thread, so a "non
// blocking" read of a 1920x1080 film still held the render loop for about
// 3 ms on an H100; into pinned memory it is a DMA the copy engine does
// while the next frame renders, and the copy into the Film happens in
// whichever thread waits for it (the frame writer's).
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <vector>

#include "opencl.h"
#include "orb/film/film.h"

namespace orb::render {

// Pinned buffers for the computed channels of one film shape, mapped once.
struct PinnedChannels {
    PinnedChannels(const cl::Context& context, cl::CommandQueue& queue, const std::array<std::size_t, film::kChannelCount>& bytes);
    ~PinnedChannels();
    PinnedChannels(const PinnedChannels&) = delete;
    PinnedChannels& operator=(const PinnedChannels&) = delete;

    cl::CommandQueue queue;  // the one they were mapped on
    std::array<cl::Buffer, film::kChannelCount> buffers;
    std::array<std::byte*, film::kChannelCount> mapped{};  // null for a channel not computed
};

// Sets of pinned buffers, one per film on its way: a set goes back to the
// pool once its film has been copied out. Safe from several threads.
class PinnedPool : public std::enable_shared_from_this<PinnedPool> {
public:
    PinnedPool(cl::Context context, std::array<std::size_t, film::kChannelCount> bytes)
        : context_(std::move(context)), bytes_(bytes) {}
    // A free set, or a new one (mapped on `queue`).
    std::shared_ptr<PinnedChannels> take(cl::CommandQueue& queue);

private:
    void give_back(PinnedChannels* set);

    cl::Context context_;
    std::array<std::size_t, film::kChannelCount> bytes_;  // per channel; 0 for one not computed
    std::mutex mutex_;
    std::vector<std::unique_ptr<PinnedChannels>> free_;
};

// The computed channels of one film, on their way.
class FilmArrival {
public:
    FilmArrival() = default;
    FilmArrival(std::vector<cl::Event> transfers, std::shared_ptr<PinnedChannels> landing, int width, int height,
                std::uint32_t channels);

    // Blocks until the transfers are done (throws cl::Error if one failed),
    // then copies the sums into `film`, shaped to hold exactly the computed
    // channels (its memory reused when it has that shape).
    void wait_into(Film& film);
    // Blocks until the transfers are done, keeping nothing.
    void wait() noexcept;

private:
    std::vector<cl::Event> transfers_;
    std::shared_ptr<PinnedChannels> landing_;
    int width_ = 0, height_ = 0;
    std::uint32_t channels_ = 0;
};

}  // namespace orb::render
