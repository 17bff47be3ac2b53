// Writes a finished frame on a thread of its own while the next frame
// renders, so encoding and writing its EXR (the largest part of what a frame
// costs besides its samples) stays off the render path. One frame at a
// time: memory holds at most one film being written besides the one
// rendering.
#pragma once

#include <exception>
#include <memory>
#include <optional>
#include <thread>

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

    BackgroundWriter() = default;
    BackgroundWriter(const BackgroundWriter&) = delete;
    BackgroundWriter& operator=(const BackgroundWriter&) = delete;
    ~BackgroundWriter();  // waits for the frame being written (its error is finish()'s to report)

    // Waits for the previous frame (rethrowing its error), then starts writing this one.
    void submit(Job job);
    // Waits for the frame being written; rethrows its error.
    void finish();
    // Seconds submit() and finish() have spent waiting for a write.
    double seconds_waited() const { return waited_; }

    // The film of a frame written already, for the next frame to read into
    // (its memory reused); an empty film when there is none.
    render::Film take_spare_film();

private:
    std::thread thread_;
    std::shared_ptr<Job> current_;  // the job being written, or last written
    std::exception_ptr error_;
    render::Film spare_;
    double waited_ = 0;
};

}  // namespace orb::render_cli
