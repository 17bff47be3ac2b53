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
#include <string>
#include <thread>
#include <vector>

#include "orb/job/frame_claim.h"
#include "orb/job/image_output.h"
#include "orb/job/messages.h"
#include "orb/job/render_film.h"

namespace orb::job {

class BackgroundWriter {
public:
    struct Job {
        FinalImage image;
        std::unique_ptr<ImageOutput> output;
        std::optional<FrameClaim> claim;  // released once the image is written
        std::string label;                // "frame 8: ", starts its lines
        // Said once the file is in place ("done: 64 spp ... -> b.0008.exr"),
        // as a warning when `warn` (a frame cut short by a signal); a frame
        // whose write fails says why instead, as an error.
        std::string written;
        bool warn = false;
    };

    // At most this many frames are written at once by default: enough to
    // overlap one frame's disk wait with the next one's compression.
    static constexpr std::size_t kDefaultInFlight = 3;

    // `messages` hears what each frame's write says (done, or why not), from the writing thread.
    explicit BackgroundWriter(MessageSink messages, std::size_t max_in_flight = kDefaultInFlight);
    BackgroundWriter(const BackgroundWriter&) = delete;
    BackgroundWriter& operator=(const BackgroundWriter&) = delete;
    ~BackgroundWriter();  // waits for every frame being written (their errors are finish()'s to report)

    // Starts writing this frame; first waits for the oldest frame in flight
    // when `max_in_flight` are. Throws (std::runtime_error, naming the
    // frames) when a frame written so far failed, each of which said why.
    void submit(Job job);
    // Waits for every frame being written; throws as submit() does.
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
    void throw_if_any_failed();

    MessageSink messages_;
    std::size_t max_in_flight_;
    std::deque<Write> in_flight_;      // oldest first
    std::vector<std::string> failed_;  // the labels of frames not written, reported once
    std::vector<Film> spare_;
    std::vector<std::shared_ptr<exr::ExrEncoding>> spare_encodings_;
    double waited_ = 0;
};

}  // namespace orb::job
