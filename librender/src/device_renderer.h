// The renderer of one device: the film and the scene in its memory, and
// render_pass over any slice of the sample sequence. A new scene (the next
// frame of an animation) replaces the old one without a new context or a
// new program build, since both belong to the device's session.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "device_decision.h"
#include "device_film.h"
#include "device_session.h"
#include "opencl.h"
#include "orb/tables/device_types.h"
#include "orb/tables/kernel_features.h"
#include "orb/render/renderer.h"
#include "pass_arguments.h"
#include "pass_tuner.h"
#include "scene_layout.h"

namespace orb::render {

// Sets the features that choose the traversal a device's programs use, for
// `scene`: one sphere at a time on GPUs (ORB_SCALAR_TRAVERSAL, with
// ORB_DRAW_ALL_NUMBERS and without leaf runs), packets of four on CPUs; no
// traversal code for a scene without a tree; NVIDIA's warp vote. Every
// program that traces rays through a scene takes them (render_pass, and
// dev/'s trace_rays).
void choose_traversal(const DeviceInfo& device, const SceneLayout& scene, device::KernelFeatures& features);

// `options` with the development knob ORB_CL_OPTIONS (knobs.cl_options)
// appended, last, so that its -D definitions win.
std::string with_development_options(std::string options, const DevelopmentKnobs& knobs);

// The features render_pass is built with for `scene` under `config` on the
// session's device (`simd_lanes` > 0: that many ORB_LANES): where the scene
// lives, the traversal, only the code the scene and the film use, the lanes.
device::KernelFeatures render_features(DeviceSession& session, const SceneLayout& scene, const RenderConfig& config,
                                       int simd_lanes);

// Its build options: those features, the register cap, then the
// development knob ORB_CL_OPTIONS.
std::string render_program_options(DeviceSession& session, const SceneLayout& scene, const RenderConfig& config,
                                   int simd_lanes);

class DeviceRenderer {
public:
    // A film of config.width x config.height (cleared) on the session's
    // device, with config's depth, mode and seed; no scene until set_scene().
    DeviceRenderer(std::shared_ptr<DeviceSession> session, const RenderConfig& config);

    const DeviceInfo& device() const { return session_->info(); }

    // Uploads the scene's tables and camera and picks the program they need
    // (built once per device for each set of build options). The film is
    // left as it is.
    void set_scene(const SceneLayout& scene, const device::CameraParams& camera);
    void set_seed(std::uint64_t seed);

    // Every channel at its clear value; the next slice writes the centre-ray
    // channels. Only the channels the kernels compute (config.film_channels)
    // live on the device at the film's size and travel to and from it.
    void clear_film();
    // Starts rendering the samples [first_sample, first_sample + count) into
    // the film and returns; wait() blocks until they are done.
    void enqueue(std::uint64_t first_sample, int count);
    void wait();

    // Adaptive sampling (config.adaptive): the pixels later passes render,
    // ascending row-major indices; every pixel until this is called. Without
    // config.adaptive the program renders every pixel and this is an error.
    void set_active_pixels(const std::vector<std::uint32_t>& pixels);
    // The same for every pixel; `on_device`: the list is made on the device
    // (with decisions there), not uploaded.
    void set_every_pixel_active(bool on_device = false);
    std::size_t active_pixel_count() const;
    // The list as the device holds it (read back: for tests).
    std::vector<std::uint32_t> active_pixels();

    // Adaptive sampling's decision on this device's film as it is, which
    // holds `samples_per_pixel` (device_decision.h): the frame's summed
    // relMSE estimate and, with `noisy_from` (the noise threshold squared;
    // config.adaptive), the active pixels narrowed to those that keep
    // sampling, on the device. None where the device has no double
    // precision: the caller decides on the host.
    std::optional<DecisionOutput> decide(std::uint64_t samples_per_pixel, std::optional<double> noisy_from);
    bool decides_on_device();

    void read_film(Film& film);    // the sums, into `film` (its memory reused); samples and ranges are the caller's
    // The same while the device goes on (DeviceFilm::read_later).
    FilmArrival read_film_later();
    void load_film(const Film& film);  // sums to continue from (centre-ray channels included when it holds samples)

    // Samples per pixel a pass should take to last the pass length aimed at
    // on this device, and the measured seconds per sample per pixel (0 until
    // a slice has been timed).
    int suggested_samples_per_pass() const;
    double seconds_per_sample() const { return tuner_.seconds_per_sample(); }

    std::uint64_t device_memory_bytes() const;
    int programs_built() const { return session_->programs_built(); }
    // Seconds spent building kernels from source (the compiler and the
    // first launch), over every scene set so far; 0 when all were loaded.
    double kernel_build_seconds() const { return kernel_build_seconds_; }

private:
    std::string build_options(const SceneLayout& scene) const;
    void choose_work_sizes();
    void bind_active_pixels();
    void pad_active_pixels();
    void prepare_kernel();
    [[noreturn]] void fail(const cl::Error& error, const std::string& what) const;

    std::shared_ptr<DeviceSession> session_;
    RenderConfig config_;
    DeviceFilm film_;
    const cl::Program* program_ = nullptr;
    bool kernel_prepared_ = false;  // prepare_kernel() has run for program_
    double kernel_build_seconds_ = 0;
    cl::Kernel kernel_;
    int simd_lanes_ = 0;  // > 0: kernel_ has this many lanes (ORB_LANES)
    SceneBuffers scene_buffers_;
    std::uint64_t scene_bytes_ = 0;
    device::RenderPassParams params_{};
    cl::NDRange local_size_;
    cl::NDRange global_size_;
    // render_pass's argument after the list (device_types.h): the active
    // pixels with adaptive sampling, their first active_count_ entries,
    // padded to global_size_; else a placeholder.
    cl::Buffer active_pixels_;
    std::size_t active_count_ = 0;
    bool every_pixel_active_ = true;  // the list is 0, 1, ..., pixels - 1
    cl::Buffer next_active_pixels_;   // where a decision on the device writes the next list
    bool decision_checked_ = false;   // decision_ was made, or the device has none
    std::unique_ptr<DeviceDecision> decision_;
    bool centre_ray_pending_ = true;  // the centre-ray channels are not yet on the film
    PassTuner tuner_;
    int pending_samples_ = 0;  // enqueued since the last wait()
    std::chrono::steady_clock::time_point pending_since_{};
};

}  // namespace orb::render
