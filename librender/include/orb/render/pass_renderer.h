// What the progressive loop and the benchmark drive: anything that adds
// samples to a film pass by pass (the OpenCL Renderer, or a test's stand-in).
#pragma once

#include <cstdint>

namespace orb::render {

class PassRenderer {
public:
    virtual ~PassRenderer() = default;

    // Samples per pixel a pass should add so that one pass stays short
    // (well under 100 ms on a GPU); tuned from the passes run so far.
    virtual int suggested_samples_per_pass() const = 0;

    // Adds `samples` samples to every pixel, the sample indices following
    // the last ones rendered; blocks until done.
    virtual void render_pass(int samples) = 0;

    // Samples per pixel in the film, resumed ones included.
    virtual std::uint64_t samples_per_pixel() const = 0;

    virtual std::uint64_t pixel_count() const = 0;

    // Pixel samples in the film, resumed ones included: fewer than
    // samples_per_pixel() x pixel_count() where adaptive sampling stopped pixels.
    virtual std::uint64_t pixel_samples() const { return samples_per_pixel() * pixel_count(); }
};

}  // namespace orb::render
