// One render pass written to a folder, so that it can be run again outside
// OpenCL: NVIDIA's OpenCL kernels are invisible to Nsight Compute, but the
// same program (NVIDIA's OpenCL binaries are PTX) launched through CUDA's
// driver API is not (dev/pass_capture/cuda_replay.cpp, docs/performance.md).
// A pass observer (librender/src/pass_observer.h): orb-capture-pass sets one
// in RenderConfig::development. It captures the first pass that adds samples
// and writes no centre ray, after letting `skip` such passes go by. A
// benchmark's first passes are short (the pass tuner starts small), and a
// short pass's lanes idle at its end, so profile a later one.
#pragma once

#include <string>

#include "device_film.h"
#include "opencl.h"
#include "orb/tables/device_types.h"
#include "pass_arguments.h"
#include "pass_observer.h"

namespace orb::render {

class PassCapture final : public PassObserver {
public:
    // Captures into the folder `dir` (made if missing).
    PassCapture(std::string dir, int skip);

    // Whether a pass has been captured.
    bool taken() const { return taken_; }

    // The pass to capture (one of the candidates once `skip` have gone by):
    // writes DIR/launch.txt (kernel name, work sizes, the program's build
    // options, one line per argument), DIR/program.bin (the program's binary
    // for the queue's device), and DIR/argN.bin, each argument's bytes before
    // the pass, and asks for pass_finished. True at most once. Throws
    // std::runtime_error when the folder cannot be written.
    bool pass_launching(cl::CommandQueue& queue, const PassLaunch& launch) override;

    // The film arguments' bytes after the pass as DIR/argN.after.bin, what a
    // replay of the same pass must reproduce; and a line on stderr naming
    // the folder.
    void pass_finished(cl::CommandQueue& queue, const PassLaunch& launch) override;

private:
    void write_inputs(cl::CommandQueue& queue, const PassLaunch& launch) const;

    std::string dir_;
    int skip_ = 0;  // candidates still to let pass
    bool taken_ = false;
};

}  // namespace orb::render
