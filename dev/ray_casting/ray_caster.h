// Casting batches of rays through a scene on a device, with nothing else:
// the trace_rays kernel (dev/ray_casting/trace_rays.cl) over the scene's
// tables, through the same traversal render_pass uses. For measuring what
// ray casting alone costs (orb-trace-benchmark: would a wavefront renderer,
// whose ray-casting kernel carries no shading state, pay?) and for testing
// the device's traversal against brute force. Not used for rendering: a
// development tool (dev/README.md), built against librender's internals.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "device_film.h"
#include "device_session.h"
#include "opencl.h"
#include "pass_arguments.h"
#include "scene_layout.h"

namespace orb::render {

// One ray as trace_rays reads it (two float4, ints in the w lanes): the
// sphere slot it leaves (-1: none) and, for a shadow ray, the light's sphere
// slot (-1: the environment).
struct CastRay {
    float origin[3];
    int self = -1;
    float direction[3];  // unit length
    int light = -1;
};
static_assert(sizeof(CastRay) == 32, "two float4 per ray, as trace_rays reads them");

struct CastHit {
    int sphere;  // slot in the layout's tables, -1 for a miss
    float t;     // distance along the ray (meaningless for a miss)
};

class RayCaster {
public:
    // Builds a program of the session's kernels and trace_rays.cl for its
    // device, with the options render_pass would be built with for `scene`
    // (the scene in __global memory; the GPU intersection on GPUs) plus
    // `extra_options` (a tool passes the ORB_CL_OPTIONS knob here), and
    // uploads the scene's tables. Throws std::runtime_error when that fails.
    RayCaster(std::shared_ptr<DeviceSession> session, const SceneLayout& scene, const std::string& extra_options = "");

    std::vector<CastHit> closest(const std::vector<CastRay>& rays);
    // Whether each ray reaches its light with nothing in the way.
    std::vector<bool> visible(const std::vector<CastRay>& rays);

    // Uploads a batch once, to be cast again and again by cast_loaded().
    void load(const std::vector<CastRay>& rays);
    // Casts the loaded batch `times` times (closest hits, or shadow rays)
    // and returns the seconds that took, from the first launch to the end of
    // the last.
    double cast_loaded(bool shadow_rays, int times);

private:
    void launch(bool shadow_rays);
    std::vector<cl_int> cast_and_read(const std::vector<CastRay>& rays, bool shadow_rays);  // two ints per ray

    std::shared_ptr<DeviceSession> session_;
    DeviceFilm film_;  // render_pass's film arguments, unused by trace_rays
    cl::Program program_;
    SceneBuffers scene_buffers_;
    cl::Kernel kernel_;
    cl::Buffer rays_, results_;
    int loaded_ = 0;
};

}  // namespace orb::render
