// Writes finished frames on threads of their own while the next frames
// render, so encoding and writing an EXR (the largest part of what a frame
// costs besides its samples) stays off the render path. Several frames may
// be in flight at once: one frame's compression leaves cores idle while it
// waits for the disk (fsync), and a fast device renders a frame in less time
// than one frame takes to encode and write. Memory holds at most
// `max_in_flight` films being written besides the one rendering.
#pragma once

#include <cstddef>
#include <deque>
#include <exception>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include "frame_claim.h"
#include "orb/cli/output_file.h"
#include "render_film.h"

namespace orb::render_cli {

class BackgroundWriter {
public:
    struct Job {
        FinalImage image;
        cli::OutputFile output;
        std::optional<FrameClaim> claim;  // released once the image is written
    };

    // At most this many frames are written at once by default: enough to
    // overlap one frame's disk wait with the next one's compression.
    static constexpr std::size_t kDefaultInFlight = 3;

    explicit BackgroundWriter(std::size_t max_in_flight = kDefaultInFlight);
    BackgroundWriter(const BackgroundWriter&) = delete;
    BackgroundWriter& operator=(const BackgroundWriter&) = delete;
    ~BackgroundWriter();  // waits for every frame being written (their errors are finish()'s to report)

    // Starts writing this frame; first waits for the oldest frame in flight
    // when `max_in_flight` are, and rethrows the first error of any frame
    // written so far.
    void submit(Job job);
    // Waits for every frame being written; rethrows the first error.
    void finish();
    // Seconds submit() and finish() have spent waiting for writes.
    double seconds_waited() const { return waited_; }

    // The film of a frame written already, for the next frame to read into
    // (its memory reused); an empty film when there is none.
    Film take_spare_film();

private:
    struct Write {
        std::shared_ptr<Job> job;
        std::shared_ptr<exr::ExrEncoding> encoding;  // memory reused by the frames that follow
        std::shared_ptr<std::exception_ptr> error;
        std::thread thread;
    };
    void wait_for_oldest();
    void rethrow_first_error();

    std::size_t max_in_flight_;
    std::deque<Write> in_flight_;  // oldest first
    std::exception_ptr error_;     // the first failure, reported once
    std::vector<Film> spare_;
    std::vector<std::shared_ptr<exr::ExrEncoding>> spare_encodings_;
    double waited_ = 0;
};

}  // namespace orb::render_cli
