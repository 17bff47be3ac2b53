// Denoising a rendered image with Intel Open Image Denoise's "RT" filter in
// HDR mode, guided by Orb's albedo and normal layers
// (docs/orb-denoise.md says what they hold and how the filter treats them).
// OIDN is loaded at run time (oidn_library.h); a Denoiser keeps its device
// and, for images of one size, its filter and buffers, so a sequence of
// frames pays for setting them up once
// (docs/design/denoising-on-the-device.md).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

namespace orb::denoise {

// Which OIDN device runs the filter. Default lets OIDN choose (a supported
// GPU if there is one, else the CPU).
enum class DeviceChoice { Default, Cpu, Cuda };
// OIDN's filter quality: High for final frames, Balanced and Fast trade
// quality for speed (interactive previews).
enum class Quality { High, Balanced, Fast };

const std::vector<std::string>& device_choice_names();  // "default", "cpu", "cuda"
const std::vector<std::string>& quality_names();        // "high", "balanced", "fast"
// Throw std::invalid_argument naming the choices.
DeviceChoice parse_device_choice(const std::string& name);
Quality parse_quality(const std::string& name);
const char* quality_name(Quality quality);

struct DenoiseSettings {
    DeviceChoice device = DeviceChoice::Default;
    Quality quality = Quality::High;
    // Denoise the albedo and normal first, each with its own RT filter, then
    // the beauty guided by them as clean images (OIDN's cleanAux): what OIDN
    // recommends for noisy guides, at three filter runs instead of one
    // (docs/design/denoising-prefiltered-guides.md has the measurements).
    bool prefilter_aux = false;
};

// One image and its guides, each width * height * 3 floats, interleaved
// (R,G,B / X,Y,Z), rows from the top.
struct DenoiseImages {
    int width = 0;
    int height = 0;
    const float* color = nullptr;   // linear HDR radiance (the beauty layer)
    const float* albedo = nullptr;  // the albedo layer
    const float* normal = nullptr;  // the normal layer (N)
};

// What denoising one image took: `seconds` in all (its inputs gathered,
// the wait for the device, the filter, the result back), of which
// `setup_seconds` waiting for the device's start (where it had not
// finished) and for the filter and buffers of a new size, and
// `filter_seconds` the filter with the copies to and from the device that
// had not run while the inputs were being gathered (Job::send).
struct DenoiseTimes {
    double seconds = 0;
    double setup_seconds = 0;
    double filter_seconds = 0;
};

struct ImageSize {
    int width = 0;
    int height = 0;
};

class Denoiser {
public:
    class Job;

    // Loads OIDN at once (throws DenoiserUnavailable when it cannot be
    // loaded), then starts the device on a thread of its own: a GPU device
    // takes about 0.3 s (CUDA's start), which a render or an EXR's decoding
    // hides. When `first_size` is given, the filter and buffers for images of
    // that size are set up on that thread too. The device's own failure
    // (say, --device cuda without a CUDA GPU) is thrown, with OIDN's
    // message, by the first call that needs the device.
    explicit Denoiser(DenoiseSettings settings, ImageSize first_size = {});
    ~Denoiser();
    Denoiser(const Denoiser&) = delete;
    Denoiser& operator=(const Denoiser&) = delete;

    // One image's turn at the device (calls from several threads take turns:
    // the device is shared). The caller writes the three inputs into the
    // job's planes, host memory the device copies from without staging
    // (pinned for a GPU), then runs it. Throws std::invalid_argument for a
    // bad size, std::runtime_error with OIDN's message when the device or
    // the filter fails.
    Job begin(int width, int height);

    // The denoised colour, width * height * 3 floats: begin, copy, run.
    // Throws std::invalid_argument for a missing image or a bad size.
    std::vector<float> denoise(const DenoiseImages& images);

    // Waits until the device has started and, where a first size was
    // given, set up and warmed up (its failure is kept for the first call
    // that needs the device). A render calls it before its first pass: a
    // GPU device's warm-up run beside a 16-spp 1080p render on the same GPU
    // took the render from 16 to 26-29 ms, for no gain in wall time.
    void wait_until_ready() const;

    // "Intel Open Image Denoise 2.5.1, RT filter, hdr, albedo and normal (not
    // clean), quality high, CPU" ("(prefiltered, clean)" with prefilter_aux):
    // what the EXR header records. These wait for the device to start and
    // throw its failure.
    const std::string& description() const;
    const std::string& version() const;      // "2.5.1"
    const std::string& device_name() const;  // "CPU", "CUDA", ...
    const DenoiseSettings& settings() const;

    // Seconds the device took to start (on its own thread), and seconds the
    // last image waited for set-up (the device's start where it had not
    // finished, the filter and buffers for a new size) and spent in the
    // filter (copies to and from the device included).
    double start_seconds() const;
    double last_setup_seconds() const;
    double last_filter_seconds() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

class Denoiser::Job {
public:
    Job(Job&&) noexcept;
    Job& operator=(Job&&) = delete;
    ~Job();

    int width() const;
    int height() const;
    // Each width * height * 3 floats, interleaved, rows from the top.
    float* color();
    float* albedo();
    float* normal();
    // Starts copying an input that is filled to the device now, so that a
    // GPU's copy runs while the caller fills the next one (a CPU device
    // reads the planes where they are). run() sends what was not sent.
    enum class Input { Color, Albedo, Normal };
    void send(Input input);
    // Runs the filter on the planes; the denoised colour (width * height * 3
    // floats) stays valid until the job ends.
    std::span<const float> run();
    // What begin() waited for set-up, and what run() took.
    double setup_seconds() const;
    double filter_seconds() const;

private:
    friend class Denoiser;
    struct Turn;
    explicit Job(std::unique_ptr<Turn> turn);
    std::unique_ptr<Turn> turn_;
};

}  // namespace orb::denoise
