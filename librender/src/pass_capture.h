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
    const std::string& build_options;
    const DeviceFilm& film;
    const SceneBuffers& scene;
    const device::RenderPassParams& params;
    cl::NDRange global;
    cl::NDRange local;
};

// The folder named by ORB_CAPTURE_PASS, or "" when the knob is not set.
std::string pass_capture_dir();
// ORB_CAPTURE_SKIP, or 0.
int pass_capture_skip();

// Writes DIR/launch.txt (kernel name, work sizes, build options, one line per
// argument), DIR/program.bin (the program's binary for the queue's device),
// and DIR/argN.bin, each argument's bytes before the pass. Throws
// std::runtime_error when the folder cannot be written.
void capture_pass_inputs(const std::string& dir, cl::CommandQueue& queue, const PassLaunch& launch);

// After the pass has finished: the film arguments' bytes as DIR/argN.after.bin,
// what a replay of the same pass must reproduce.
void capture_pass_outputs(const std::string& dir, cl::CommandQueue& queue, const DeviceFilm& film);

}  // namespace orb::render
