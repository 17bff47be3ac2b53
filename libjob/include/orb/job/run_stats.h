// --stats-json: the figures of one run, for farms and CI dashboards.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "orb/denoise/denoiser.h"
#include "orb/render/device.h"
#include "orb/render/renderer.h"

namespace orb::job {

struct DeviceShare {
    render::DeviceInfo device;
    std::uint64_t spp = 0;  // samples per pixel this device rendered into the image
};

struct RunStats {
    render::DeviceInfo device;        // the first device
    std::vector<DeviceShare> devices;  // every device, with its share (several with --device all or a list)
    int width = 0;
    int height = 0;
    std::uint64_t spp = 0;           // samples per pixel in the image, resumed ones included
    std::uint64_t spp_this_run = 0;  // samples per pixel this run added
    std::uint64_t samples = 0;           // pixel samples in the image (adaptive sampling skips stopped pixels)
    std::uint64_t samples_this_run = 0;  // pixel samples this run drew
    // Adaptive sampling: the image's estimated relMSE at the last decision, and the pixels still sampling then.
    std::optional<double> estimated_relmse;
    std::optional<std::size_t> active_pixels;
    std::optional<int> decisions;            // adaptive sampling's decisions in this run
    std::optional<double> decision_seconds;  // and their time (part of `seconds`)
    std::optional<denoise::DenoiseTimes> denoise;  // --denoise: the denoiser's times on the final image (not in `seconds`)
    int passes = 0;
    double seconds = 0;              // this run's rendering (or timed benchmark) time
    double samples_per_second = 0;   // pixel samples per second over `seconds`
    std::uint64_t device_memory_bytes = 0;
    std::size_t bvh_nodes = 0;        // the scene's BVH (0: none, as for a few spheres)
    double bvh_seconds = 0;           // building (or, for a frame, refitting) it
    std::optional<double> setup_seconds;  // from starting to read the scene until the devices could render
    double kernel_build_seconds = 0;      // of setup: building kernels from source (0: loaded from the cache)
    std::optional<double> startup_seconds;  // from the process's start to its first pass (a front end's still)
    std::string stop_reason;         // "spp", "time", "interrupted" or "benchmark"
    std::string output;              // "" for --benchmark
    std::string sample_ranges;       // the sample indices in the image, "0:64"; "" for --benchmark
    std::optional<long> frame;       // --frame/--frames: the frame number
};

// What the renderer itself tells: its devices and their shares, the image
// size, device memory and spp; the caller adds the run's own figures.
RunStats renderer_stats(const render::Renderer& renderer);

std::string stats_json(const RunStats& stats);

// --frames: {"frames": [one object per frame rendered], "skipped": [...]}.
std::string frames_stats_json(const std::vector<RunStats>& frames, const std::vector<long>& skipped);

}  // namespace orb::job
