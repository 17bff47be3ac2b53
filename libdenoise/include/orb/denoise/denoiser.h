// Denoising a rendered image with Intel Open Image Denoise's "RT" filter in
// HDR mode, guided by Orb's albedo and normal layers
// (docs/orb-denoise.md says what they hold and how the filter treats them).
// OIDN is loaded at run time (oidn_library.h); a Denoiser keeps its device
// and, for images of one size, its filter and buffers, so a sequence of
// frames pays for setting them up once.
#pragma once

#include <memory>
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

class Denoiser {
public:
    // Loads OIDN and creates the device. Throws DenoiserUnavailable when OIDN
    // cannot be loaded, std::runtime_error when the device cannot be created
    // (say, --device cuda without a CUDA GPU), with OIDN's message.
    explicit Denoiser(DenoiseSettings settings);
    ~Denoiser();
    Denoiser(const Denoiser&) = delete;
    Denoiser& operator=(const Denoiser&) = delete;

    // The denoised colour, width * height * 3 floats. Safe to call from
    // several threads (calls run one at a time: the device is shared).
    // Throws std::invalid_argument for a missing image or a bad size,
    // std::runtime_error with OIDN's message when the filter fails.
    std::vector<float> denoise(const DenoiseImages& images);

    // "Intel Open Image Denoise 2.5.1, RT filter, hdr, albedo and normal (not
    // clean), quality high, CPU" ("(prefiltered, clean)" with prefilter_aux):
    // what the EXR header records.
    const std::string& description() const;
    const std::string& version() const;  // "2.5.1"
    const std::string& device_name() const;  // "CPU", "CUDA", ...
    const DenoiseSettings& settings() const;

    // Seconds the last denoise() spent setting up the filter and buffers
    // (0 when the size was the last one's) and running it (the copies to and
    // from the device included): what a sequence pays once, and per frame.
    double last_setup_seconds() const;
    double last_filter_seconds() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace orb::denoise
