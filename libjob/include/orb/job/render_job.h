// Rendering an in-memory scene from another program (an embedding such as
// a Python module): one still image, rendered by the same plan and film
// code as orb-render (orb/job/film_plan.h, orb/job/film_render.h), so that
// the same scene, seed and samples give the same pixels bit for bit as
// `orb-render scene.orb --seed S --spp N -o image.exr`.
//
// Nothing here prints: progress comes through the callback, warnings
// through StillSettings::on_message; nothing installs a signal handler:
// the caller owns the cancel flag (docs/design/render-job-library.md).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "orb/denoise/denoiser.h"
#include "orb/exr/film_exr.h"
#include "orb/exr/passes.h"
#include "orb/film/film.h"
#include "orb/job/messages.h"
#include "orb/job/run_stats.h"
#include "orb/scene/scene.h"

namespace orb::job {

struct RenderedImage;

// One image of an in-memory scene: what orb-render's options say of a
// still, with orb-render's defaults.
struct StillSettings {
    // 0: the scene's render block (its width and height), as orb-render without --width/--height.
    int width = 0, height = 0;
    // Samples per pixel; 0: the scene's render block, as orb-render without --spp.
    std::uint64_t spp = 64;
    std::uint64_t seed = 0;                // as --seed
    // As --device: "default" (or ""): the fastest GPU, else the CPU; "all";
    // an index of list_devices(), a name's substring, or a comma-separated list.
    std::string device = "default";
    // The layers asked for, as --passes; --denoise adds its guides (albedo,
    // normal) and adaptive sampling its layers, as orb-render does.
    std::vector<exr::Pass> passes = {exr::Pass::Beauty};
    bool denoise = false;                  // as --denoise: the image gains the `denoised` layer
    std::optional<double> target_error;    // as --target-error
    std::optional<double> noise_threshold; // as --noise-threshold
    std::optional<double> time_limit;      // as --time SECONDS: the render stops after the pass that passes it
    // Empty: the scene's render block, else Orb's default, as orb-render
    // without --mode/--sampler/--max-depth.
    std::string mode;
    std::string sampler;
    std::optional<int> max_depth;
    bool half = false;                     // as --half: HALF colour layers
    // What orb:sceneFile records (orb-render records the scene's path).
    std::string label = "<memory>";
    // Warnings and notes (a slow kernel build, sums out of range); none: dropped.
    MessageSink on_message;
    // Snapshots while rendering, for a live preview of the converging image:
    // the image so far (the mean of the samples drawn, taken between passes
    // as orb-render --checkpoint takes its checkpoints), handed over after
    // the first pass, then every `snapshot_seconds` seconds or every
    // `snapshot_passes` passes (neither: after every pass) while more passes
    // follow; the render's end is render_still's result, never a snapshot.
    // Called on the rendering thread, the devices idle until it returns.
    std::function<void(RenderedImage&& snapshot)> on_snapshot;
    double snapshot_seconds = 0;
    int snapshot_passes = 0;
};

// A render's progress after a pass (as orb-render's progress line shows it).
struct Progress {
    int pass = 0;
    std::uint64_t spp = 0;         // samples per pixel in the film
    std::uint64_t target_spp = 0;  // where the render is heading
    double elapsed_seconds = 0;
    double samples_per_second = 0;
};

// The film so far, for a live preview: read back from the devices when
// asked (which takes time, so a preview reads it every few passes). Valid
// only during the callback it is handed to.
class PreviewAccess {
public:
    explicit PreviewAccess(std::function<void(Film&)> read) : read_(std::move(read)) {}
    // Fills `into` (its memory reused from call to call) with the film's sums and sample count.
    void read_film(Film& into) const { read_(into); }
    Film film() const {
        Film film;
        read_(film);
        return film;
    }

private:
    std::function<void(Film&)> read_;
};

// Called after each pass; returning false stops the render cleanly after
// that pass, as SIGINT stops orb-render (the image holds what was rendered).
using ProgressCallback = std::function<bool(const Progress&, const PreviewAccess&)>;

// One layer of the image as the EXR file holds it.
struct Layer {
    std::string name;                   // "beauty", "albedo", "denoised", ...
    std::vector<std::string> channels;  // the channel names in the file ("R", "G", "B", "A"; "albedo.R", ...)
    int width = 0, height = 0;
    std::vector<float> pixels;          // row-major from the top row, channels interleaved (HALF read as float)
};

// The rendered image: what orb-render writes for this render.
struct RenderedImage {
    Film film;
    exr::ExrMetadata metadata;     // orb:renderSeconds and orb:device are this run's
    exr::ExrWriteOptions options;  // layers, HALF, compression (orb-render's default, ZIP) and exact sums
    std::shared_ptr<denoise::Denoiser> denoiser;  // --denoise: computes the `denoised` layer when encoded
    bool stopped = false;  // stopped short (the callback, the cancel flag or the time limit), not finished
    bool snapshot = false; // StillSettings::on_snapshot's: the film while it rendered, more passes following
    RunStats stats;        // what orb-render --stats-json says of it (no output path)

    // Each layer as the EXR holds it: beauty, the requested passes, and
    // `denoised` when asked (not the exact sums, which are internal).
    std::vector<Layer> layers() const;
    // The EXR file's bytes; the same as orb-render's file of this render
    // apart from the attributes that say when and where it ran
    // (orb:renderSeconds, orb:device).
    std::string encode_exr() const;
    std::string encode_exr(exr::ExrCompression compression) const;
    void save_exr(const std::string& path) const;  // written to a temporary file, then renamed into place
};

// Renders `scene` (at its rest pose, time 0) as orb-render renders a still.
// The scene is taken as orb-render has it once read: its environment map's
// texels loaded (orb::exr::load_environment_map), as orb::import_scene's
// callers do. The development knobs of the environment (ORB_CL_OPTIONS,
// ORB_KERNEL_DIR, ...) are not read: an embedding renders with the
// installed kernels, as orb-render does without them.
// Returns once the render reaches its samples, time limit or adaptive
// goal, the callback returns false, or *cancel becomes true (checked after
// each pass). Throws orb::InputError for a scene or settings orb-render
// refuses, with the same message; std::runtime_error when stopped before
// the first pass finished (there is no image then).
RenderedImage render_still(const Scene& scene, const StillSettings& settings, const ProgressCallback& progress = {},
                           const std::atomic<bool>* cancel = nullptr);

// One OpenCL device, as orb-render --list-devices prints it.
struct DeviceListing {
    int index = 0;             // what --device INDEX takes
    std::string type;          // "gpu", "cpu" or "other"
    unsigned compute_units = 0;
    std::uint64_t memory_bytes = 0;
    std::string platform;
    std::string name;
    std::string vendor;   // the device's vendor and OpenCL version, which the list leaves out
    std::string version;
};
// Throws orb::render::NoOpenCLError (whose message says how to install PoCL) without any OpenCL platform.
std::vector<DeviceListing> list_devices();

}  // namespace orb::job
