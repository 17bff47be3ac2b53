// The OpenCL path tracer. One work-item per pixel sample; a pass adds
// `samples` samples to every pixel of the film kept on the device.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "orb/kernels/device_types.h"
#include "orb/render/device.h"
#include "orb/render/film.h"
#include "orb/scene/scene.h"

namespace orb::render {

// Global (path tracing) or Direct (the paper's local illumination): the
// kernels' enum, from kernels/include/orb/kernels/device_types.h.
using IntegratorMode = device::IntegratorMode;
// Sobol (low discrepancy, the default) or Independent (Philox): the kernels' enum.
using SamplerKind = device::SamplerKind;

struct RenderConfig {
    int width = 640;
    int height = 480;
    int max_depth = 6;
    IntegratorMode mode = IntegratorMode::Global;
    std::uint64_t seed = 0;
    SamplerKind sampler = SamplerKind::Sobol;
    std::string device;       // selector for choose_device()
    std::string kernel_dir;   // development override of the embedded kernels ("" = embedded; env ORB_KERNEL_DIR too)
    bool use_binary_cache = true;  // $XDG_CACHE_HOME/orb (or ~/.cache/orb)
    bool use_bvh = true;  // false: every ray tests every sphere (for tests and comparisons; same image)
};

class Renderer {
public:
    // Chooses the device, builds (or loads cached) kernels, uploads the scene.
    // Throws std::runtime_error with the build log if the kernels do not build.
    Renderer(const Scene& scene, const RenderConfig& config);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    const DeviceInfo& device() const;
    const RenderConfig& config() const;

    // Samples per pixel a pass should add so that one pass stays short on this
    // device (well under 100 ms on a GPU); tuned from the passes run so far.
    int suggested_samples_per_pass() const;

    // Adds `samples` samples per pixel, sample indices continuing from
    // samples_per_pixel(); blocks until done. The RNG is counter-based, so the
    // result depends only on the seed and on which sample indices were taken.
    void render_pass(int samples);

    std::uint64_t samples_per_pixel() const;

    Film read_film() const;            // copies the sums back from the device
    void load_film(const Film& film);  // resume: continue from these sums and count

    std::uint64_t device_memory_bytes() const;  // buffers this renderer allocated

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

struct BenchmarkResult {
    double samples_per_second = 0;
    std::uint64_t samples = 0;  // timed samples (pixels x spp)
    double seconds = 0;
    int passes = 0;
};

// Warm-up passes, then timed passes for about `seconds`, no image written.
BenchmarkResult run_benchmark(Renderer& renderer, double seconds);

}  // namespace orb::render
