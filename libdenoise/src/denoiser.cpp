#include "orb/denoise/denoiser.h"

#include <chrono>
#include <cstddef>
#include <mutex>
#include <stdexcept>
#include <utility>

#include "oidn_api.h"
#include "orb/denoise/oidn_library.h"

namespace orb::denoise {
namespace {

const char* device_type_name(int type) {
    switch (type) {
        case oidn::kDeviceCpu: return "CPU";
        case oidn::kDeviceSycl: return "SYCL";
        case oidn::kDeviceCuda: return "CUDA";
        case oidn::kDeviceHip: return "HIP";
        case oidn::kDeviceMetal: return "Metal";
        default: return "unknown device";
    }
}

oidn::DeviceType device_type(DeviceChoice choice) {
    switch (choice) {
        case DeviceChoice::Cpu: return oidn::kDeviceCpu;
        case DeviceChoice::Cuda: return oidn::kDeviceCuda;
        case DeviceChoice::Default: break;
    }
    return oidn::kDeviceDefault;
}

oidn::Quality oidn_quality(Quality quality) {
    switch (quality) {
        case Quality::Balanced: return oidn::kQualityBalanced;
        case Quality::Fast: return oidn::kQualityFast;
        case Quality::High: break;
    }
    return oidn::kQualityHigh;
}

template <typename Enum>
Enum parse_choice(const std::string& name, const std::vector<std::string>& names, const char* what) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (name == names[i]) return static_cast<Enum>(i);
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown " + std::string(what) + " '" + name + "' (expected " + list + ")");
}

}  // namespace

// In the order of the enumerators.
const std::vector<std::string>& device_choice_names() {
    static const std::vector<std::string> names{"default", "cpu", "cuda"};
    return names;
}
const std::vector<std::string>& quality_names() {
    static const std::vector<std::string> names{"high", "balanced", "fast"};
    return names;
}
DeviceChoice parse_device_choice(const std::string& name) {
    return parse_choice<DeviceChoice>(name, device_choice_names(), "denoising device");
}
Quality parse_quality(const std::string& name) { return parse_choice<Quality>(name, quality_names(), "quality"); }
const char* quality_name(Quality quality) { return quality_names()[static_cast<std::size_t>(quality)].c_str(); }

struct Denoiser::State {
    const oidn::Api& api;
    DenoiseSettings settings;
    oidn::Device device = nullptr;
    std::string version;
    std::string device_name;
    std::string description;

    // The filters and buffers for the last image size; rebuilt when it changes.
    oidn::Filter filter = nullptr;
    oidn::Filter albedo_filter = nullptr, normal_filter = nullptr;  // prefilter_aux only
    oidn::Buffer color = nullptr, albedo = nullptr, normal = nullptr, output = nullptr;
    int width = 0, height = 0;
    std::mutex mutex;
    double setup_seconds = 0, filter_seconds = 0;

    explicit State(const oidn::Api& oidn_api) : api(oidn_api) {}

    // Throws OIDN's pending error on `device` (null: the error of the last
    // device creation on this thread), if any.
    void check(oidn::Device on, const std::string& doing) const {
        const char* message = nullptr;
        const oidn::Error error = api.oidnGetDeviceError(on, &message);
        if (error != oidn::kErrorNone)
            throw std::runtime_error("denoiser (Intel Open Image Denoise): " + doing + " failed: " +
                                     (message && *message ? message : "error " + std::to_string(error)));
    }

    void release_filter() {
        for (oidn::Filter* f : {&filter, &albedo_filter, &normal_filter})
            if (*f) api.oidnReleaseFilter(std::exchange(*f, nullptr));
        for (oidn::Buffer* b : {&color, &albedo, &normal, &output})
            if (*b) api.oidnReleaseBuffer(std::exchange(*b, nullptr));
        width = height = 0;
    }

    void prepare(int w, int h) {
        if (filter && w == width && h == height) return;
        release_filter();
        const std::size_t bytes = static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3 * sizeof(float);
        for (oidn::Buffer* b : {&color, &albedo, &normal, &output}) {
            *b = api.oidnNewBuffer(device, bytes);
            check(device, "allocating an image of " + std::to_string(w) + "x" + std::to_string(h));
        }
        const auto image = [&](oidn::Filter to, const char* name, oidn::Buffer buffer) {
            api.oidnSetFilterImage(to, name, buffer, oidn::kFormatFloat3, static_cast<std::size_t>(w),
                                   static_cast<std::size_t>(h), 0, 0, 0);
        };
        filter = new_filter();
        image(filter, "color", color);
        image(filter, "albedo", albedo);
        image(filter, "normal", normal);
        image(filter, "output", output);
        // Orb's beauty is linear radiance of any range.
        api.oidnSetFilterBool(filter, "hdr", true);
        // The albedo and normal are Monte Carlo means of as many samples as
        // the beauty: noisy behind glass and at edges. Either OIDN filters
        // them inside the beauty's filter (cleanAux false, the default, said
        // explicitly), or, with prefilter_aux, each is denoised first by an
        // RT filter of its own, in place, as OIDN's documentation describes,
        // and the beauty's filter takes them as clean.
        api.oidnSetFilterBool(filter, "cleanAux", settings.prefilter_aux);
        commit(filter, "the RT filter");
        if (settings.prefilter_aux) {
            albedo_filter = new_filter();
            image(albedo_filter, "albedo", albedo);
            image(albedo_filter, "output", albedo);
            commit(albedo_filter, "the albedo's prefilter");
            normal_filter = new_filter();
            image(normal_filter, "normal", normal);
            image(normal_filter, "output", normal);
            commit(normal_filter, "the normal's prefilter");
        }
        width = w;
        height = h;
    }

    oidn::Filter new_filter() {
        oidn::Filter made = api.oidnNewFilter(device, "RT");
        check(device, "creating the RT filter");
        return made;
    }
    void commit(oidn::Filter f, const std::string& what) {
        api.oidnSetFilterInt(f, "quality", oidn_quality(settings.quality));
        api.oidnCommitFilter(f);
        check(device, "setting up " + what);
    }

    void execute(oidn::Filter f, const char* doing) {
        api.oidnExecuteFilter(f);
        check(device, doing);
    }

    ~State() {
        release_filter();
        if (device) api.oidnReleaseDevice(device);
    }
};

Denoiser::Denoiser(DenoiseSettings settings) {
    state_ = std::make_unique<State>(load_oidn());
    State& s = *state_;
    s.settings = settings;
    s.device = s.api.oidnNewDevice(device_type(settings.device));
    if (!s.device) {
        s.check(nullptr, std::string("creating the ") + device_choice_names()[static_cast<std::size_t>(settings.device)] +
                             " device");
        throw std::runtime_error("denoiser (Intel Open Image Denoise): no " +
                                 device_choice_names()[static_cast<std::size_t>(settings.device)] + " device");
    }
    s.api.oidnCommitDevice(s.device);
    s.check(s.device, "starting the device");
    const int version = s.api.oidnGetDeviceInt(s.device, "version");  // major * 10000 + minor * 100 + patch
    s.version = std::to_string(version / 10000) + "." + std::to_string(version / 100 % 100) + "." +
                std::to_string(version % 100);
    s.device_name = device_type_name(s.api.oidnGetDeviceInt(s.device, "type"));
    s.description = "Intel Open Image Denoise " + s.version + ", RT filter, hdr, albedo and normal " +
                    (settings.prefilter_aux ? "(prefiltered, clean)" : "(not clean)") + ", quality " +
                    quality_name(settings.quality) + ", " + s.device_name;
}

Denoiser::~Denoiser() = default;

std::vector<float> Denoiser::denoise(const DenoiseImages& images) {
    if (images.width <= 0 || images.height <= 0)
        throw std::invalid_argument("denoiser: an image of " + std::to_string(images.width) + "x" +
                                    std::to_string(images.height) + " pixels");
    if (!images.color || !images.albedo || !images.normal)
        throw std::invalid_argument("denoiser: the colour, albedo and normal images are all needed");
    State& s = *state_;
    const std::lock_guard lock(s.mutex);
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    s.prepare(images.width, images.height);
    const Clock::time_point prepared = Clock::now();
    const std::size_t floats = static_cast<std::size_t>(images.width) * static_cast<std::size_t>(images.height) * 3;
    const std::size_t bytes = floats * sizeof(float);
    s.api.oidnWriteBuffer(s.color, 0, bytes, images.color);
    s.api.oidnWriteBuffer(s.albedo, 0, bytes, images.albedo);
    s.api.oidnWriteBuffer(s.normal, 0, bytes, images.normal);
    s.check(s.device, "copying the image to the device");
    if (s.albedo_filter) s.execute(s.albedo_filter, "denoising the albedo");
    if (s.normal_filter) s.execute(s.normal_filter, "denoising the normal");
    s.execute(s.filter, "denoising");
    std::vector<float> result(floats);
    s.api.oidnReadBuffer(s.output, 0, bytes, result.data());
    s.check(s.device, "copying the result back");
    s.setup_seconds = std::chrono::duration<double>(prepared - start).count();
    s.filter_seconds = std::chrono::duration<double>(Clock::now() - prepared).count();
    return result;
}

const std::string& Denoiser::description() const { return state_->description; }
const std::string& Denoiser::version() const { return state_->version; }
const std::string& Denoiser::device_name() const { return state_->device_name; }
const DenoiseSettings& Denoiser::settings() const { return state_->settings; }
double Denoiser::last_setup_seconds() const { return state_->setup_seconds; }
double Denoiser::last_filter_seconds() const { return state_->filter_seconds; }

}  // namespace orb::denoise
