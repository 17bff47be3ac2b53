// One render pass written to a folder, so that it can be run again outside
// OpenCL: NVIDIA's OpenCL kernels are invisible to Nsight Compute, but the
// same program (NVIDIA's OpenCL binaries are PTX) launched through CUDA's
// driver API is not (tests/render/cuda_replay.cpp, docs/performance.md).
// Development knobs: ORB_CAPTURE_PASS=DIR captures the first pass that adds
// samples and writes no centre ray, after skipping ORB_CAPTURE_SKIP (default
// 0) such passes. A benchmark's first passes are short (the pass tuner starts
// small), and a short pass's lanes idle at its end, so profile a later one.
#pragma once

#include <string>

#include "device_film.h"
#include "opencl.h"
#include "orb/kernels/device_types.h"
#include "pass_arguments.h"

namespace orb::render {

struct PassLaunch {
    const cl::Program& program;
    const cl::Kernel& kernel;
    const DeviceFilm& film;
    const SceneBuffers& scene;
    const device::RenderPassParams& params;
    cl::NDRange global;
    cl::NDRange local;
};

// One renderer's capture: the knobs, read once, and whether the pass has
// been taken.
class PassCapture {
public:
    PassCapture();  // reads ORB_CAPTURE_PASS and ORB_CAPTURE_SKIP

    // Whether the pass about to be enqueued is the one to capture (counting
    // it among the candidates when it could be); true at most once.
    bool take(bool writes_centre_ray);

    // Writes DIR/launch.txt (kernel name, work sizes, the program's build
    // options, one line per argument), DIR/program.bin (the program's binary
    // for the queue's device), and DIR/argN.bin, each argument's bytes before
    // the pass. Throws std::runtime_error when the folder cannot be written.
    void write_inputs(cl::CommandQueue& queue, const PassLaunch& launch) const;

    // After the pass has finished: the film arguments' bytes as
    // DIR/argN.after.bin, what a replay of the same pass must reproduce; and
    // a line on stderr naming the folder.
    void write_outputs(cl::CommandQueue& queue, const DeviceFilm& film, int samples_per_pixel) const;

private:
    std::string dir_;  // "" when the knob is not set
    int skip_ = 0;     // candidates still to let pass
    bool taken_ = false;
};

}  // namespace orb::render
