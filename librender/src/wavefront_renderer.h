// A wavefront path tracer built from render_pass's own code
// (kernels/wavefront.cl), for measuring whether a wavefront design beats
// the megakernel (docs/performance.md, "A wavefront renderer, measured").
// Not used for rendering: it computes the radiance alone, in global mode,
// `paths_per_pixel` samples of every pixel per wave.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "device_film.h"
#include "device_session.h"
#include "opencl.h"
#include "orb/render/renderer.h"
#include "pass_arguments.h"
#include "scene_layout.h"

namespace orb::render {

class WavefrontRenderer {
public:
    // Builds the wavefront kernels with the options render_pass gets for
    // `scene` and `config` on the session's device, plus `extra_options`,
    // and allocates `paths_per_pixel` paths per pixel (a wave's paths: more
    // of them make each launch longer against its fixed cost). Throws
    // std::invalid_argument for direct mode, std::runtime_error when
    // building or allocating fails.
    WavefrontRenderer(std::shared_ptr<DeviceSession> session, const SceneLayout& scene,
                      const device::CameraParams& camera, const RenderConfig& config, int paths_per_pixel = 1,
                      const std::string& extra_options = "");

    // Enqueues waves of samples from `first_sample` on, `waves` of them,
    // each of paths_per_pixel() samples per pixel, adding their radiance to
    // the sums.
    void enqueue(std::uint64_t first_sample, int waves);
    int paths_per_pixel() const { return paths_per_pixel_; }
    void finish();
    // Every pixel's summed radiance, rgb, rows from the top; waits for the device.
    std::vector<float> radiance_sums();
    void clear();

    std::uint64_t path_state_bytes() const { return path_bytes_; }

    // One wave from `first_sample`, waiting for each launch to end, with
    // the seconds each kind of kernel took and the queues' lengths: where a
    // wave's time goes. The radiance is added to the sums as by enqueue().
    struct WaveProfile {
        double begin = 0, intersect = 0, shade = 0, shadow = 0;  // seconds, counter resets with shade
        std::vector<int> paths;        // paths cast at each scattering event (0: camera rays)
        std::vector<int> shadow_rays;  // shadow rays cast after each event's shading
    };
    WaveProfile profile_wave(std::uint64_t first_sample);

private:
    // With `profile`, waits for each launch and fills it in.
    void enqueue_wave(std::uint64_t first_sample, WaveProfile* profile = nullptr);
    [[noreturn]] void fail(const cl::Error& error, const std::string& what) const;

    std::shared_ptr<DeviceSession> session_;
    device::RenderPassParams params_{};
    int pixels_ = 0;
    int paths_per_pixel_ = 1;
    int max_depth_ = 0;
    cl::NDRange global_size_;
    std::uint64_t path_bytes_ = 0;
    DeviceFilm film_;  // render_pass's film arguments, unused by these kernels
    SceneBuffers scene_buffers_;
    cl::Kernel begin_, intersect_, shade_, shadow_;
    cl::Buffer paths_, queues_[2], counts_, hits_, shadow_rays_, radiance_;
};

}  // namespace orb::render
