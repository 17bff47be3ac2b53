// Adaptive sampling's decision on the device (kernels/adaptive.cl,
// docs/design/adaptive-sampling.md): each pixel's estimated relMSE from the
// film's sums where they were rendered, the stopping rule and the
// neighbour rule, the new list of active pixels compacted there, and the
// frame's estimate; only DecisionTotals come back. It decides exactly as
// the host's reference (libfilm's pixel_relmse, frame_relmse and
// pixels_still_sampling) does on the same film.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>

#include "device_film.h"
#include "device_session.h"
#include "opencl.h"

namespace orb::render {

struct DecisionInput {
    // Samples every pixel holds, read where the film computes no
    // sample_count channel (a uniform render).
    double uniform_samples = 0;
    // A pixel is noisy from this relMSE on (the noise threshold squared);
    // none: only the frame's estimate is made, no list.
    std::optional<double> noisy_from;
    // The pixels still sampling: the first `candidate_count` entries of
    // `candidates`, ascending, or every pixel (then `candidates` is not read).
    const cl::Buffer* candidates = nullptr;
    std::size_t candidate_count = 0;
    bool every_pixel = false;
    // Where the candidates that keep sampling go, in their order; it holds
    // at least candidate_count entries.
    cl::Buffer* still_sampling = nullptr;
};

struct DecisionOutput {
    double error_sum = 0;  // the pixels' estimated relMSEs, added (the frame's estimate times the pixel count)
    std::size_t still_sampling = 0;  // entries written to DecisionInput::still_sampling
};

class DeviceDecision {
public:
    // The decision for films of width x height on the session's device, or
    // null where the device has no double precision.
    static std::unique_ptr<DeviceDecision> make(DeviceSession& session, int width, int height);

    DeviceDecision(const cl::Context& context, const cl::Program& program, int width, int height);

    // Enqueues the decision on `queue` after the work enqueued before (the
    // passes) and waits for its totals.
    DecisionOutput decide(cl::CommandQueue& queue, const DeviceFilm& film, const DecisionInput& input);

    // Enqueues the list of every pixel, 0, 1, ..., into `list` (which holds
    // that many entries).
    void list_every_pixel(cl::CommandQueue& queue, cl::Buffer& list);

    // Launches each kernel once over nothing, so that a driver's work at a
    // kernel's first launch happens while the renderer is set up, not in
    // the first decision, whose seconds the render reports.
    void prepare(cl::CommandQueue& queue, const DeviceFilm& film);

private:
    // The launches over `pixels` pixels (every kernel, even over none, when `every_kernel`).
    DecisionOutput run(cl::CommandQueue& queue, const DeviceFilm& film, const DecisionInput& input, std::size_t pixels,
                       bool every_kernel);

    int width_;
    int height_;
    cl::Kernel estimate_;
    cl::Kernel count_;
    cl::Kernel sum_;
    cl::Kernel compact_;
    cl::Kernel every_;
    cl::Buffer noisy_;             // a byte per pixel: 1 for a noisy one
    cl::Buffer group_error_sums_;  // a double per group of pixels
    cl::Buffer group_counts_;      // per group of candidates: how many keep sampling
    cl::Buffer group_offsets_;     // and where they go in the new list
    cl::Buffer totals_;            // one DecisionTotals
};

}  // namespace orb::render
