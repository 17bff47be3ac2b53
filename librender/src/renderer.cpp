#include "orb/render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <set>
#include <stdexcept>
#include <thread>

#include "animation_tree.h"
#include "device_renderer.h"
#include "device_session.h"
#include "memory_check.h"
#include "sample_split.h"
#include "scene_layout.h"

namespace orb::render {
namespace {

void check_config(const RenderConfig& config)
{
    if (config.width <= 0 || config.height <= 0)
        throw std::invalid_argument("image size must be positive, got " + std::to_string(config.width) + "x" +
                                    std::to_string(config.height));
    if (config.max_depth < 0) throw std::invalid_argument("max depth must not be negative");
}

}  // namespace

struct Renderer::Impl {
    RenderConfig config;
    std::vector<DeviceInfo> infos;
    std::vector<std::unique_ptr<DeviceRenderer>> devices;
    std::vector<SampleRanges> device_ranges;  // what each device's film holds
    SampleRanges ranges;                      // their union: what the film holds
    std::uint64_t cursor = 0;                 // where render_pass() continues
    std::uint64_t pixel_samples = 0;          // pixel samples in the film (adaptive sampling leaves pixels out)
    bool film_clear = true;                   // every device film is at its clear values (new frames skip a clear)
    AnimationTree tree;                       // the BVH, refitted from frame to frame while that pays
    double frame_render_seconds = 0;          // spent in render_samples since the scene was set
    double last_frame_seconds = 0;            // frame_render_seconds of the last scene replaced (prepare_scene reads it)
    TreeReport tree_in_use;                   // the uploaded scene's tree (the AnimationTree may be a frame ahead)
    bool tree_in_use_refitted = false;
    // Another device's film on its way into the one read_film() returns,
    // kept so that its memory is reused read after read (read_film() is
    // therefore not for two threads at once).
    mutable Film device_part;

    std::vector<int> split(int count) const;
    void wait_all(const std::vector<std::size_t>& busy);
    void all_pixels_active();  // adaptive sampling: every pixel renders again
    // Adaptive sampling decides on the device, where it can. One device
    // holds the whole film; several hold a slice of the samples each, which
    // only the host adds. A CPU's OpenCL (PoCL) holds the film in the host's
    // memory, and the host's decision on its cores measured faster than the
    // kernels there (docs/design/adaptive-sampling.md).
    bool wants_device_decisions() const
    {
        return devices.size() == 1 && config.development.device_decisions.value_or(!infos.front().is_cpu);
    }
};

std::vector<int> Renderer::Impl::split(int count) const
{
    if (devices.size() == 1) return {count};
    // Each device as fast as measured so far (in this frame or earlier ones:
    // set_scene keeps the devices' renderers), or as its kind and size
    // suggest until it has been timed.
    std::vector<DeviceSpeed> speeds;
    for (std::size_t d = 0; d < devices.size(); ++d)
        speeds.push_back({devices[d]->seconds_per_sample(), prior_speed(infos[d])});
    return split_pass(count, speeds);
}

void Renderer::Impl::wait_all(const std::vector<std::size_t>& busy)
{
    if (busy.size() == 1) {
        devices[busy[0]]->wait();
        return;
    }
    // One waiting thread per device, so each device's time is its own (the
    // split of the next pass depends on it), not the time until the slowest
    // device ahead of it in a sequential wait finished.
    std::vector<std::exception_ptr> errors(busy.size());
    std::vector<std::thread> waiters;
    for (std::size_t i = 0; i < busy.size(); ++i)
        waiters.emplace_back([&, i] {
            try {
                devices[busy[i]]->wait();
            } catch (...) {
                errors[i] = std::current_exception();
            }
        });
    for (std::thread& waiter : waiters) waiter.join();
    for (const std::exception_ptr& error : errors)
        if (error) std::rethrow_exception(error);
}

void Renderer::Impl::all_pixels_active()
{
    // Made on the device where it decides: a frame's list then never crosses the bus.
    for (auto& device : devices) device->set_every_pixel_active(wants_device_decisions());
}

struct PreparedScene::Data {
    SceneLayout layout;
    device::CameraParams camera{};
    Renderer::TreeReport tree;
    bool refitted = false;
};

PreparedScene::PreparedScene() = default;
PreparedScene::~PreparedScene() = default;
PreparedScene::PreparedScene(PreparedScene&&) noexcept = default;
PreparedScene& PreparedScene::operator=(PreparedScene&&) noexcept = default;

Renderer::Renderer(const Scene& scene, const RenderConfig& config) : impl_(std::make_unique<Impl>())
{
    Impl& r = *impl_;
    check_config(config);
    r.config = config;
    r.tree = AnimationTree(config.development.refit_cost_limit);
    // The scene is checked before any device is touched, so bad input fails fast.
    PreparedScene prepared = prepare_scene(scene);
    r.infos = choose_devices(config.device);
    // And the memory the render needs, before a driver is asked for it.
    {
        std::vector<DeviceNeeds> needs(r.infos.size());
        const std::vector<std::uint64_t> scene_buffers = scene_table_buffer_bytes(prepared.data_->layout.tables);
        for (DeviceNeeds& device : needs) {
            device.buffers = DeviceFilm::buffer_bytes(config.width, config.height, config.film_channels);
            device.buffers.insert(device.buffers.end(), scene_buffers.begin(), scene_buffers.end());
        }
        require_memory(r.infos, needs, config.caller_host_bytes, host_bytes_available());
    }
    const SessionOptions options{config.development.kernel_dir, config.use_binary_cache,
                                 config.development.show_build_log};
    for (const DeviceInfo& info : r.infos)
        r.devices.push_back(std::make_unique<DeviceRenderer>(DeviceSession::open(info, options), config));
    r.device_ranges.resize(r.devices.size());
    set_scene(std::move(prepared));
}

Renderer::~Renderer() = default;

const DeviceInfo& Renderer::device() const { return impl_->infos.front(); }
const std::vector<DeviceInfo>& Renderer::devices() const { return impl_->infos; }
const RenderConfig& Renderer::config() const { return impl_->config; }

PreparedScene Renderer::prepare_scene(const Scene& scene)
{
    Impl& r = *impl_;
    PreparedScene prepared;
    prepared.data_ = std::make_unique<PreparedScene::Data>();
    PreparedScene::Data& data = *prepared.data_;
    data.layout = layout_scene(scene, r.tree.tree_for(scene, r.config.use_bvh, r.last_frame_seconds));
    data.camera = layout_camera(scene.camera, r.config.width, r.config.height);
    data.tree = {r.tree.node_count(), r.tree.last_seconds()};
    data.refitted = r.tree.last_refitted();
    return prepared;
}

void Renderer::set_scene(const Scene& scene)
{
    impl_->last_frame_seconds = impl_->frame_render_seconds;  // the frame just ended weighs this refit
    set_scene(prepare_scene(scene));
}

void Renderer::set_scene(PreparedScene&& scene)
{
    Impl& r = *impl_;
    if (!scene.data_) throw std::invalid_argument("set_scene: no prepared scene");
    const PreparedScene::Data& data = *scene.data_;
    for (auto& device : r.devices) device->set_scene(data.layout, data.camera);
    r.tree_in_use = data.tree;
    r.tree_in_use_refitted = data.refitted;
    r.last_frame_seconds = r.frame_render_seconds;
    r.frame_render_seconds = 0;
    clear();
}

bool Renderer::last_tree_refitted() const { return impl_->tree_in_use_refitted; }

Renderer::TreeReport Renderer::tree_report() const { return impl_->tree_in_use; }

void Renderer::set_seed(std::uint64_t seed)
{
    impl_->config.seed = seed;
    for (auto& device : impl_->devices) device->set_seed(seed);
    clear();
}

void Renderer::clear(std::uint64_t first_sample)
{
    Impl& r = *impl_;
    if (!r.film_clear)
        for (auto& device : r.devices) device->clear_film();
    r.film_clear = true;
    for (SampleRanges& ranges : r.device_ranges) ranges = {};
    r.ranges = {};
    r.cursor = first_sample;
    r.pixel_samples = 0;
    if (r.config.adaptive) r.all_pixels_active();
}

int Renderer::suggested_samples_per_pass() const
{
    // The devices run side by side, so each can take a pass of its own length.
    int total = 0;
    for (const auto& device : impl_->devices)
        total = static_cast<int>(std::min<long long>(std::numeric_limits<int>::max() / 2,
                                                     static_cast<long long>(total) + device->suggested_samples_per_pass()));
    return total;
}

void Renderer::render_pass(int samples)
{
    if (samples < 0) throw std::invalid_argument("a pass cannot add a negative number of samples");
    render_samples(impl_->cursor, samples);
}

void Renderer::render_samples(std::uint64_t first_sample, int count)
{
    if (count < 0) throw std::invalid_argument("a pass cannot add a negative number of samples");
    if (count == 0) return;
    Impl& r = *impl_;
    const SampleRange range{first_sample, static_cast<std::uint64_t>(count)};
    if (first_sample > std::numeric_limits<std::uint64_t>::max() - range.count)
        throw std::invalid_argument("samples " + std::to_string(first_sample) + " + " + std::to_string(count) +
                                    " run past the last sample index 2^64-1");
    if (r.ranges.total() + range.count > film::kMaxSamplesPerPixel)
        throw std::invalid_argument("a film holds at most 2^39 samples per pixel; " + std::to_string(count) +
                                    " more would make " + std::to_string(r.ranges.total() + range.count));
    if (r.ranges.overlaps(range))
        throw std::invalid_argument("the film already holds some of the samples " + std::to_string(first_sample) +
                                    ":" + std::to_string(count) + " (it holds " + r.ranges.format() + ")");

    r.film_clear = false;
    const auto start = std::chrono::steady_clock::now();
    // Each device takes the next contiguous slice of the range.
    const std::vector<int> shares = r.split(count);
    std::vector<std::size_t> busy;
    std::uint64_t next = first_sample;
    for (std::size_t d = 0; d < r.devices.size(); ++d) {
        if (shares[d] == 0) continue;
        r.devices[d]->enqueue(next, shares[d]);
        r.device_ranges[d].add(SampleRange{next, static_cast<std::uint64_t>(shares[d])});
        next += static_cast<std::uint64_t>(shares[d]);
        busy.push_back(d);
    }
    r.wait_all(busy);
    r.frame_render_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.ranges.add(range);
    r.cursor = range.end();
    r.pixel_samples += range.count * active_pixel_count();
}

std::uint64_t Renderer::samples_per_pixel() const { return impl_->ranges.total(); }
std::uint64_t Renderer::pixel_count() const
{
    return static_cast<std::uint64_t>(impl_->config.width) * static_cast<std::uint64_t>(impl_->config.height);
}
std::uint64_t Renderer::pixel_samples() const { return impl_->pixel_samples; }

void Renderer::set_active_pixels(const std::vector<std::uint32_t>& pixels)
{
    if (!impl_->config.adaptive) throw std::logic_error("set_active_pixels needs RenderConfig::adaptive");
    for (auto& device : impl_->devices) device->set_active_pixels(pixels);
}

std::size_t Renderer::active_pixel_count() const
{
    return impl_->config.adaptive ? impl_->devices.front()->active_pixel_count() : pixel_count();
}

std::vector<std::uint32_t> Renderer::active_pixels() const
{
    if (!impl_->config.adaptive) throw std::logic_error("active_pixels needs RenderConfig::adaptive");
    return impl_->devices.front()->active_pixels();
}

bool Renderer::decides_on_device() const
{
    const Impl& r = *impl_;
    return r.wants_device_decisions() && r.devices.front()->decides_on_device();
}

std::optional<Renderer::Decision> Renderer::decide_on_device(std::optional<double> noise_threshold)
{
    if (!decides_on_device()) return std::nullopt;
    if (noise_threshold && !impl_->config.adaptive)
        throw std::logic_error("a noise threshold needs RenderConfig::adaptive");
    // Compared as relMSE, as the host's rule does: sqrt(e) >= t is e >= t^2.
    const std::optional<double> noisy_from =
        noise_threshold ? std::optional<double>(*noise_threshold * *noise_threshold) : std::nullopt;
    const std::optional<DecisionOutput> output =
        impl_->devices.front()->decide(impl_->device_ranges.front().total(), noisy_from);
    if (!output) return std::nullopt;
    return Decision{output->error_sum / static_cast<double>(pixel_count()), output->still_sampling};
}

std::uint64_t Renderer::next_sample() const { return impl_->cursor; }
const SampleRanges& Renderer::sample_ranges() const { return impl_->ranges; }
const std::vector<SampleRanges>& Renderer::device_sample_ranges() const { return impl_->device_ranges; }

Film Renderer::read_film() const
{
    Film film;
    read_film(film);
    return film;
}

void Renderer::read_film(Film& film) const
{
    Impl& r = *impl_;
    bool first = true;
    for (std::size_t d = 0; d < r.devices.size(); ++d) {
        if (r.device_ranges[d].empty()) continue;
        if (first) {
            // The common case of one device: straight into `film`, no additions.
            r.devices[d]->read_film(film);
            film.samples_per_pixel = r.device_ranges[d].total();
            film.sample_ranges = r.device_ranges[d];
            first = false;
            continue;
        }
        Film& part = r.device_part;
        r.devices[d]->read_film(part);
        part.samples_per_pixel = r.device_ranges[d].total();
        part.sample_ranges = r.device_ranges[d];
        film.accumulate(part, r.config.film_channels);  // the others are empty in both
    }
    if (first) film.resize(r.config.width, r.config.height, r.config.film_channels);  // no samples yet: an empty film
}

struct PendingFilm::State {
    struct Part {
        FilmArrival arrival;
        std::uint64_t samples_per_pixel = 0;
        SampleRanges ranges;
    };
    std::vector<Part> parts;  // one per device that holds samples, the first into the caller's film
    int width = 0, height = 0;
    std::uint32_t channels = film::kAllChannels;
};

PendingFilm::PendingFilm() = default;
PendingFilm::~PendingFilm()
{
    if (state_)
        for (State::Part& part : state_->parts) part.arrival.wait();
}
PendingFilm::PendingFilm(PendingFilm&&) noexcept = default;
PendingFilm& PendingFilm::operator=(PendingFilm&&) noexcept = default;

void PendingFilm::wait(Film& film)
{
    if (!state_) return;
    const std::unique_ptr<State> state = std::move(state_);
    if (state->parts.empty()) {
        film.resize(state->width, state->height, state->channels);  // no samples yet: an empty film
        return;
    }
    try {
        Film other;
        for (std::size_t p = 0; p < state->parts.size(); ++p) {
            State::Part& part = state->parts[p];
            Film& into = p == 0 ? film : other;
            part.arrival.wait_into(into);
            into.samples_per_pixel = part.samples_per_pixel;
            into.sample_ranges = part.ranges;
            if (p > 0) film.accumulate(other, state->channels);  // the others are empty in both
        }
    } catch (const cl::Error& error) {
        for (State::Part& part : state->parts) part.arrival.wait();
        throw std::runtime_error("reading the film back failed: " + describe_cl_error(error));
    }
}

PendingFilm Renderer::read_film_later() const
{
    Impl& r = *impl_;
    PendingFilm pending;
    pending.state_ = std::make_unique<PendingFilm::State>();
    PendingFilm::State& state = *pending.state_;
    state.width = r.config.width;
    state.height = r.config.height;
    state.channels = r.config.film_channels;
    for (std::size_t d = 0; d < r.devices.size(); ++d) {
        if (r.device_ranges[d].empty()) continue;
        state.parts.push_back({r.devices[d]->read_film_later(), r.device_ranges[d].total(), r.device_ranges[d]});
    }
    return pending;
}

void Renderer::load_film(const Film& film)
{
    Impl& r = *impl_;
    const SampleRanges held = film.held_ranges();
    r.film_clear = false;
    r.devices.front()->load_film(film);
    for (std::size_t d = 1; d < r.devices.size(); ++d) r.devices[d]->clear_film();
    for (SampleRanges& ranges : r.device_ranges) ranges = {};
    r.device_ranges.front() = held;
    r.ranges = held;
    r.cursor = held.end();
    const std::vector<film::Sum>& counts = film.sample_count;
    if (counts.empty()) {
        r.pixel_samples = held.total() * pixel_count();
    } else {
        std::uint64_t total = 0;
        for (const film::Sum count : counts) total += static_cast<std::uint64_t>(count);
        r.pixel_samples = total;
    }
    if (r.config.adaptive) r.all_pixels_active();
}

std::uint64_t Renderer::device_memory_bytes() const
{
    std::uint64_t total = 0;
    for (const auto& device : impl_->devices) total += device->device_memory_bytes();
    return total;
}

double Renderer::kernel_build_seconds() const
{
    double longest = 0;
    for (const auto& device : impl_->devices) longest = std::max(longest, device->kernel_build_seconds());
    return longest;
}

int Renderer::programs_built() const
{
    int total = 0;
    for (const auto& device : impl_->devices) total += device->programs_built();
    return total;
}

}  // namespace orb::render
