// The OpenCL path tracer's front: one film, rendered by one device or split
// over several. One work-item per pixel; a pass adds samples to every pixel.
//
// Underneath (librender/src): a DeviceSession per device (context, queue and
// the built programs, shared by every renderer in the process) and a
// DeviceRenderer per device (its film and scene, rendering any slice of the
// sample sequence). The RNG is counter-based, so a sample is a pure function
// of (pixel, sample index, seed): the front gives each device its own slice
// of indices and sums their films, and the image depends only on which
// indices were rendered, not on the devices, passes or runs.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "orb/tables/device_types.h"
#include "orb/render/development_knobs.h"
#include "orb/render/device.h"
#include "orb/film/film.h"
#include "orb/render/pass_renderer.h"
#include "orb/film/sample_ranges.h"
#include "orb/scene/scene.h"

namespace orb::render {

// Global (path tracing) or Direct (the paper's local illumination): the
// kernels' enum, from libtables/include/orb/tables/device_types.h.
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
    std::string device;       // selector for choose_devices(): one device, a list, or "all"
    bool use_binary_cache = true;  // $XDG_CACHE_HOME/orb (or ~/.cache/orb)
    bool use_bvh = true;  // false: every ray tests every sphere (for tests and comparisons; same image)
    // The film channels the kernels compute (bits of film::channel_bit;
    // film::channels_for(layers) for the layers a run writes): the others
    // stay at their clear values and cost nothing.
    std::uint32_t film_channels = film::kAllChannels;
    // Host memory the caller will need beside the renderer's, for the
    // renderer's check that the render fits before anything is allocated
    // (memory_check.h): orb-render's film read back and its EXR encoding.
    std::uint64_t caller_host_bytes = 0;
    // Adaptive sampling: passes render only the pixels of
    // Renderer::set_active_pixels (the kernels' ORB_ACTIVE_PIXELS); false
    // renders every pixel, without the list's indirection.
    bool adaptive = false;
    // Settings for measuring and debugging (development_knobs.h); the
    // defaults render as a user's run does.
    DevelopmentKnobs development;
    // Called, from the thread that builds, when the kernels for a scene are
    // being built from source (not loaded from the binary cache) and the build
    // has taken a second: builds take seconds, tens on a CPU through PoCL, so
    // a tool can say why it waits. Never for a program loaded from the cache.
    std::function<void()> on_slow_kernel_build;
};

// A scene laid out for the devices, its BVH built or refitted: what
// Renderer::set_scene uploads, made ahead by Renderer::prepare_scene (the
// next frame's, on another thread, while this frame renders).
class PreparedScene {
public:
    PreparedScene();
    ~PreparedScene();
    PreparedScene(PreparedScene&&) noexcept;
    PreparedScene& operator=(PreparedScene&&) noexcept;

private:
    friend class Renderer;
    struct Data;
    std::unique_ptr<Data> data_;
};

// A film on its way back from the devices (Renderer::read_film_later).
class PendingFilm {
public:
    PendingFilm();
    ~PendingFilm();  // waits for the transfers still under way (their memory is the caller's)
    PendingFilm(PendingFilm&&) noexcept;
    PendingFilm& operator=(PendingFilm&&) noexcept;

    // Blocks until the sums have arrived and puts them into `film` (its
    // memory reused when it has the renderer's shape), with their sample
    // count and ranges, the devices' parts added. Throws
    // std::runtime_error if a transfer failed.
    void wait(Film& film);

private:
    friend class Renderer;
    struct State;
    std::unique_ptr<State> state_;
};

class Renderer final : public PassRenderer {
public:
    // Chooses the device(s), builds (or loads cached) kernels, uploads the
    // scene. Throws std::runtime_error with the build log if the kernels do
    // not build, std::invalid_argument for a bad size or depth.
    Renderer(const Scene& scene, const RenderConfig& config);
    ~Renderer() override;
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    const DeviceInfo& device() const;  // the first device
    const std::vector<DeviceInfo>& devices() const;
    const RenderConfig& config() const;

    // A new scene of the same size and settings (the next frame): its
    // tables and camera are uploaded, the programs already built on each
    // device are reused when the scene needs the same build options (it
    // rebuilds only if, say, a BVH appears). The film is emptied. A scene
    // with as many spheres as the last keeps the last one's BVH, refitted to
    // the moved spheres, while the time that saves over a new build exceeds
    // what the refitted tree is expected to add to a frame like the last
    // (animation_tree.h); else a new one is built.
    void set_scene(const Scene& scene);
    // The host's part of set_scene, ahead of it: the scene checked and laid
    // out, its tree refitted from the last prepared one or built. It may run
    // on another thread while this renderer renders (it touches neither the
    // devices nor the film), but not beside another prepare_scene or
    // set_scene. A refit then weighs the last frame whose scene was
    // replaced, not the one rendering.
    PreparedScene prepare_scene(const Scene& scene);
    // Uploads a prepared scene (set_scene's device part); the film is emptied.
    void set_scene(PreparedScene&& scene);
    // Whether the current scene's BVH is the previous scene's refitted.
    bool last_tree_refitted() const;
    // The current scene's BVH: its nodes (0: no tree, as for a scene of a
    // few spheres), and the seconds building or refitting it took.
    struct TreeReport {
        std::size_t nodes = 0;
        double seconds = 0;
    };
    TreeReport tree_report() const;
    // Another seed; the film is emptied.
    void set_seed(std::uint64_t seed);
    // Empties the film; render_pass() continues from sample `first_sample`.
    void clear(std::uint64_t first_sample = 0);

    int suggested_samples_per_pass() const override;
    // Adds `samples` samples per pixel, continuing from next_sample().
    void render_pass(int samples) override;
    // Adds exactly the samples [first_sample, first_sample + count), split
    // over the devices in contiguous slices so that the pass is expected to
    // end as early as it can (sample_split.h): a device gets none unless its
    // share ends the pass at least 5% sooner than the others would alone.
    // Speeds are measured pass by pass and kept across frames; a device not
    // yet timed is judged by its kind and compute units. Throws
    // std::invalid_argument if the film already holds any of them.
    void render_samples(std::uint64_t first_sample, int count);

    std::uint64_t samples_per_pixel() const override;
    std::uint64_t pixel_count() const override;
    // Pixel samples in the film: samples_per_pixel() x pixel_count() unless
    // adaptive sampling left pixels out of passes.
    std::uint64_t pixel_samples() const override;

    // Adaptive sampling (config().adaptive): the pixels the following passes
    // render, as ascending row-major indices (every pixel after clear() or
    // load_film()). Throws std::logic_error without config().adaptive,
    // std::invalid_argument for indices out of order or outside the image.
    void set_active_pixels(const std::vector<std::uint32_t>& pixels);
    std::size_t active_pixel_count() const;
    // The list as the (first) device holds it, read back.
    std::vector<std::uint32_t> active_pixels() const;

    // Whether adaptive sampling's decisions run on the device, where the
    // film is (decide_on_device): with one device that has double
    // precision and is not a CPU, or as the development knob
    // device_decisions says.
    bool decides_on_device() const;
    // The decision on the device (docs/design/adaptive-sampling.md), the
    // same as libfilm's on the film read back: the frame's estimated relMSE
    // and, with a noise threshold (config().adaptive), the active pixels
    // narrowed on the device to those that keep sampling, of which
    // `still_sampling` are left. None where !decides_on_device().
    struct Decision {
        double estimated_relmse = 0;
        std::size_t still_sampling = 0;
    };
    std::optional<Decision> decide_on_device(std::optional<double> noise_threshold);
    std::uint64_t next_sample() const;
    const SampleRanges& sample_ranges() const;
    // The samples each device has rendered into the film, in devices() order
    // (empty for a device too slow to shorten any pass by 5%: not used).
    const std::vector<SampleRanges>& device_sample_ranges() const;

    // The film: every device's sums added, with the sample count and ranges.
    // Only the channels of config().film_channels come from the devices; the
    // others hold their clear values.
    Film read_film() const;
    // The same into `film`, reusing its memory when it has this size (frame
    // after frame, a reused film costs no fresh pages). One thread at a time.
    void read_film(Film& film) const;
    // The film as read_film() gives it, without waiting for it: each device
    // copies its film on the device and sends the copy into pinned host
    // memory on a queue of its own, so the transfer overlaps whatever is
    // rendered next (the next frame); PendingFilm::wait gives it.
    PendingFilm read_film_later() const;
    // Continue from these sums: render_pass() then follows the film's
    // highest sample index. The film must have this renderer's size; only
    // its channels of config().film_channels are uploaded.
    void load_film(const Film& film);

    std::uint64_t device_memory_bytes() const;  // buffers allocated, over all devices
    int programs_built() const;                 // kernel programs built or loaded, over all devices
    // Seconds the kernels took to build from source (compiler and first
    // launch) on the slowest device, over every scene set so far; 0 when
    // they came from the binary cache.
    double kernel_build_seconds() const;

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
BenchmarkResult run_benchmark(PassRenderer& renderer, double seconds);

}  // namespace orb::render
