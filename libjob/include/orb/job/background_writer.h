// Writes finished frames on threads of their own while the next frames
// render, so encoding and writing an EXR (the largest part of what a frame
// costs besides its samples) stays off the render path. Several frames are
// encoded and flushed at once, one worker each (every frame's blocks are
// compressed on all cores besides), and put in place in frame order
// (orb/job/ordered_writes.h): a fast device renders a frame in less time
// than one frame takes to encode and write, and one frame's disk wait would
// leave the cores idle. Memory holds at most `max_in_flight` films being
// written besides the one rendering.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "orb/job/frame_claim.h"
#include "orb/job/image_output.h"
#include "orb/job/messages.h"
#include "orb/job/ordered_writes.h"
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

    // How many frames of `bytes_per_frame` (the film and its encoding) are
    // written at once: one per core, so that encoders waiting for the disk
    // leave no core idle, 3 at least (one frame's disk wait overlaps the next
    // one's compression even on two cores) and 16 at most, and no more than
    // a quarter of the host's memory holds.
    static std::size_t frames_in_flight(std::uint64_t bytes_per_frame);

    // `messages` hears what each frame's write says (done, or why not), from the writing threads.
    BackgroundWriter(MessageSink messages, std::size_t max_in_flight);
    BackgroundWriter(const BackgroundWriter&) = delete;
    BackgroundWriter& operator=(const BackgroundWriter&) = delete;
    // Waits for every frame being written, which each say how it went
    // (their errors are finish()'s to throw).
    ~BackgroundWriter() = default;

    // Starts writing this frame; first waits for the oldest frame in flight
    // when `max_in_flight` are. Throws (std::runtime_error, naming the
    // frames) when a frame written so far failed, each of which said why;
    // no frame after a failed one is put in place.
    void submit(Job job);
    // Waits for every frame being written; throws as submit() does.
    void finish();
    // Seconds submit() and finish() have spent waiting for writes.
    double seconds_waited() const { return waited_; }
    std::size_t max_in_flight() const { return writes_.max_in_flight(); }

    // The film of a frame written already, for the next frame to read into
    // (its memory reused); an empty film when there is none.
    Film take_spare_film();

private:
    void take_back(std::vector<OrderedWrites::Done> writes);  // their films and encodings for reuse
    void throw_if_any_failed();

    MessageSink messages_;
    std::vector<std::string> failed_;  // the labels of frames not written, reported once
    std::vector<Film> spare_;
    std::vector<std::unique_ptr<exr::ExrEncoding>> spare_encodings_;
    double waited_ = 0;
    OrderedWrites writes_;  // last: destroyed first, waiting for the frames in flight
};

}  // namespace orb::job
