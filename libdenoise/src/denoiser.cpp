#include "orb/denoise/denoiser.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstring>
#include <future>
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
    double start_seconds = 0;
    // Whether the filter reads host memory as it is (a CPU device), so the
    // planes are the filter's own images and nothing is copied.
    bool host_is_device = false;

    // The filters and buffers for the last image size; rebuilt when it
    // changes. `planes` are the host memory the caller fills and reads
    // (color, albedo, normal, output), pinned for a GPU device, which copies
    // them to and from `images` asynchronously.
    oidn::Filter filter = nullptr;
    oidn::Filter albedo_filter = nullptr, normal_filter = nullptr;  // prefilter_aux only
    std::array<oidn::Buffer, 4> planes{};
    std::array<oidn::Buffer, 4> images{};
    std::array<bool, 3> sent{};  // the inputs already on their way to `images` this turn
    int width = 0, height = 0;
    std::mutex mutex;
    double setup_seconds = 0, filter_seconds = 0;
    // The device's start, on its own thread (the constructor).
    std::shared_future<void> started;

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

    void start() {
        const auto began = std::chrono::steady_clock::now();
        const std::string choice = device_choice_names()[static_cast<std::size_t>(settings.device)];
        device = api.oidnNewDevice(device_type(settings.device));
        if (!device) {
            check(nullptr, "creating the " + choice + " device");
            throw std::runtime_error("denoiser (Intel Open Image Denoise): no " + choice + " device");
        }
        api.oidnCommitDevice(device);
        check(device, "starting the device");
        const int number = api.oidnGetDeviceInt(device, "version");  // major * 10000 + minor * 100 + patch
        version = std::to_string(number / 10000) + "." + std::to_string(number / 100 % 100) + "." +
                  std::to_string(number % 100);
        const int type = api.oidnGetDeviceInt(device, "type");
        host_is_device = type == oidn::kDeviceCpu;
        device_name = device_type_name(type);
        description = "Intel Open Image Denoise " + version + ", RT filter, hdr, albedo and normal " +
                      (settings.prefilter_aux ? "(prefiltered, clean)" : "(not clean)") + ", quality " +
                      quality_name(settings.quality) + ", " + device_name;
        start_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    }

    void release_filter() {
        for (oidn::Filter* f : {&filter, &albedo_filter, &normal_filter})
            if (*f) api.oidnReleaseFilter(std::exchange(*f, nullptr));
        for (std::array<oidn::Buffer, 4>* set : {&planes, &images})
            for (oidn::Buffer& b : *set)
                if (b) {
                    // A CPU device's planes are its images: released once.
                    if (set == &images && host_is_device) b = nullptr;
                    else api.oidnReleaseBuffer(std::exchange(b, nullptr));
                }
        width = height = 0;
    }

    std::size_t plane_bytes() const {
        return static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3 * sizeof(float);
    }
    float* plane(std::size_t i) const { return static_cast<float*>(api.oidnGetBufferData(planes[i])); }

    void prepare(int w, int h) {
        if (filter && w == width && h == height) return;
        release_filter();
        const std::size_t bytes = static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3 * sizeof(float);
        const std::string size = std::to_string(w) + "x" + std::to_string(h);
        for (oidn::Buffer& b : planes) {
            b = api.oidnNewBufferWithStorage(device, bytes, oidn::kStorageHost);
            check(device, "allocating host memory for an image of " + size);
        }
        for (std::size_t i = 0; i < images.size(); ++i) {
            images[i] = host_is_device ? planes[i] : api.oidnNewBuffer(device, bytes);
            check(device, "allocating an image of " + size);
        }
        const auto image = [&](oidn::Filter to, const char* name, oidn::Buffer buffer) {
            api.oidnSetFilterImage(to, name, buffer, oidn::kFormatFloat3, static_cast<std::size_t>(w),
                                   static_cast<std::size_t>(h), 0, 0, 0);
        };
        const auto [color, albedo, normal, output] = images;
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

    // An input to the device, in the filter's queue, once a turn.
    void send(std::size_t input) {
        if (host_is_device || sent[input]) return;
        api.oidnWriteBufferAsync(images[input], 0, plane_bytes(), plane(input));
        sent[input] = true;
    }

    // The inputs not yet sent, the filters, the output back, in one queue;
    // a CPU device filters the planes where they are.
    void run() {
        const std::size_t bytes = plane_bytes();
        for (std::size_t i = 0; i < 3; ++i) send(i);
        if (albedo_filter) api.oidnExecuteFilterAsync(albedo_filter);
        if (normal_filter) api.oidnExecuteFilterAsync(normal_filter);
        api.oidnExecuteFilterAsync(filter);
        if (!host_is_device) api.oidnReadBufferAsync(images[3], 0, bytes, plane(3));
        api.oidnSyncDevice(device);
        check(device, "denoising");
    }

    // A GPU's first run of the filter loads its kernels (CUDA loads modules
    // lazily): 11-13 ms instead of 5.5 at 1920x1080 on an H200. Run once on
    // blank planes while nothing waits. A CPU device is not warmed: its run
    // is the work itself (seconds), and has nothing to load.
    void warm_up() {
        if (host_is_device) return;
        for (std::size_t i = 0; i < 3; ++i) std::memset(plane(i), 0, plane_bytes());
        run();
    }

    ~State() {
        if (started.valid()) started.wait();
        release_filter();
        if (device) api.oidnReleaseDevice(device);
    }
};

struct Denoiser::Job::Turn {
    State& state;
    std::unique_lock<std::mutex> lock;
    double setup_seconds = 0;
    double filter_seconds = 0;
};

Denoiser::Denoiser(DenoiseSettings settings, ImageSize first_size) {
    state_ = std::make_unique<State>(load_oidn());
    state_->settings = settings;
    State& s = *state_;
    s.started = std::async(std::launch::async, [&s, first_size] {
                    s.start();
                    if (first_size.width > 0 && first_size.height > 0) {
                        s.prepare(first_size.width, first_size.height);
                        s.warm_up();
                    }
                }).share();
}

Denoiser::~Denoiser() = default;

Denoiser::Job Denoiser::begin(int width, int height) {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("denoiser: an image of " + std::to_string(width) + "x" + std::to_string(height) +
                                    " pixels");
    State& s = *state_;
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    std::unique_lock lock(s.mutex);
    s.started.get();  // the device's failure, if it failed
    s.prepare(width, height);
    s.sent = {};  // a new turn: nothing of it sent yet
    s.setup_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return Job(std::make_unique<Job::Turn>(Job::Turn{s, std::move(lock), s.setup_seconds}));
}

std::vector<float> Denoiser::denoise(const DenoiseImages& images) {
    if (!images.color || !images.albedo || !images.normal)
        throw std::invalid_argument("denoiser: the colour, albedo and normal images are all needed");
    Job job = begin(images.width, images.height);
    const std::size_t floats = static_cast<std::size_t>(images.width) * static_cast<std::size_t>(images.height) * 3;
    std::copy_n(images.color, floats, job.color());
    std::copy_n(images.albedo, floats, job.albedo());
    std::copy_n(images.normal, floats, job.normal());
    const std::span<const float> result = job.run();
    return {result.begin(), result.end()};
}

const std::string& Denoiser::description() const {
    state_->started.get();
    return state_->description;
}
const std::string& Denoiser::version() const {
    state_->started.get();
    return state_->version;
}
const std::string& Denoiser::device_name() const {
    state_->started.get();
    return state_->device_name;
}
void Denoiser::wait_until_ready() const { state_->started.wait(); }
const DenoiseSettings& Denoiser::settings() const { return state_->settings; }
double Denoiser::start_seconds() const {
    state_->started.get();
    return state_->start_seconds;
}
double Denoiser::last_setup_seconds() const { return state_->setup_seconds; }
double Denoiser::last_filter_seconds() const { return state_->filter_seconds; }

Denoiser::Job::Job(std::unique_ptr<Turn> turn) : turn_(std::move(turn)) {}
Denoiser::Job::Job(Job&&) noexcept = default;
Denoiser::Job::~Job() = default;
int Denoiser::Job::width() const { return turn_->state.width; }
int Denoiser::Job::height() const { return turn_->state.height; }
float* Denoiser::Job::color() { return turn_->state.plane(0); }
float* Denoiser::Job::albedo() { return turn_->state.plane(1); }
float* Denoiser::Job::normal() { return turn_->state.plane(2); }
void Denoiser::Job::send(Input input) { turn_->state.send(static_cast<std::size_t>(input)); }

std::span<const float> Denoiser::Job::run() {
    State& s = turn_->state;
    const auto start = std::chrono::steady_clock::now();
    s.run();
    s.filter_seconds = turn_->filter_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {s.plane(3), s.plane_bytes() / sizeof(float)};
}
double Denoiser::Job::setup_seconds() const { return turn_->setup_seconds; }
double Denoiser::Job::filter_seconds() const { return turn_->filter_seconds; }

}  // namespace orb::denoise
