// A seam for development code around each render pass: what the renderer is
// about to launch, before it is enqueued, and the same launch once it has
// finished. The renderer does nothing else for it; what to do with a pass
// (write it to a folder for a replay outside OpenCL, say: dev/pass_capture)
// is the observer's. Set through RenderConfig::development.pass_observer.
#pragma once

#include "device_film.h"
#include "opencl.h"
#include "orb/tables/device_types.h"
#include "pass_arguments.h"

namespace orb::render {

// One render pass as the renderer launches it: the program and its kernel,
// with every argument bound (the film, the scene's tables, the parameters),
// and the work sizes.
struct PassLaunch {
    const cl::Program& program;
    const cl::Kernel& kernel;
    const DeviceFilm& film;
    const SceneBuffers& scene;
    const device::RenderPassParams& params;
    const cl::Buffer& active_pixels;  // the argument after the list (device_types.h)
    cl::NDRange global;
    cl::NDRange local;
};

class PassObserver {
public:
    virtual ~PassObserver() = default;

    // Before the pass is enqueued on `queue` (nothing of it has run yet).
    // True asks for pass_finished: the renderer then waits for this pass
    // before it returns, so observe few passes where timing matters.
    virtual bool pass_launching(cl::CommandQueue& queue, const PassLaunch& launch) = 0;
    // After a pass for which pass_launching returned true has finished.
    virtual void pass_finished(cl::CommandQueue& queue, const PassLaunch& launch) = 0;
};

}  // namespace orb::render
