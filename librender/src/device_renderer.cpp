#include "device_renderer.h"

#include <algorithm>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <utility>

#include "pass_observer.h"
#include "program_build.h"

namespace orb::render {
namespace {

// NVIDIA's compiler gives render_pass more registers than let an SM keep
// enough warps in flight, or, capped too low, spills. Measured on an H100
// (docs/design/register-caps.md and nvidia-fault-36.md): with a tree the traversal's memory waits want warps, and
// 64 beats 80, 96 and 128 at 1 M spheres (0.752 G samples/s against 0.698,
// 0.660 and 0.633 at 1920x1080; at 1 k spheres 64 to 96 are within 2%);
// without one, the Cornell boxes (nine spheres, three packets, long paths)
// ran best at 72 (+3% over 80, 96 lost 3%) and the small open scenes (three
// to five spheres in one or two packets, short paths) at 96 (+4% to +13%
// over 80). Nsight Compute, through a CUDA replay of a pass, shows both
// kinds' occupancy limited by these registers (docs/design/register-caps.md);
// why the two kinds want different caps is not known.
int nvidia_register_cap(const cl::Device& device, const SceneLayout& scene)
{
    const std::string extensions = device.getInfo<CL_DEVICE_EXTENSIONS>();
    if (extensions.find("cl_nv_compiler_options") == std::string::npos) return 0;
    if (scene.counts.bvh_node_count > 0) return 64;
    return scene.counts.packet_count <= 2 ? 80 : 72;
}

// The camera paths per work-item of render_pass (ORB_LANES, kernels/lanes.cl)
// on this device beyond one, or 0 for one. CPUs only: a GPU already runs
// work-items in its lanes. The device's native float vector width: 16 with
// AVX-512, 8 with AVX2.
int simd_lanes(const DeviceInfo& info, const cl::Device& device, const DevelopmentKnobs& knobs)
{
    if (info.is_gpu) return 0;
    int lanes = static_cast<int>(device.getInfo<CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT>());
    if (knobs.simd_lanes) lanes = *knobs.simd_lanes;  // development knob ORB_SIMD_LANES: 0 is off
    return lanes >= 16 ? 16 : lanes >= 8 ? 8 : lanes >= 4 ? 4 : 0;
}

// Pass lengths aimed at: short on GPUs so no display watchdog fires and
// progress stays smooth; longer on CPUs, where per-pass overhead matters more.
constexpr double kGpuPassSeconds = 0.05;
constexpr double kCpuPassSeconds = 0.25;

void check_config(const RenderConfig& config)
{
    if (config.width <= 0 || config.height <= 0)
        throw std::invalid_argument("image size must be positive, got " + std::to_string(config.width) + "x" +
                                    std::to_string(config.height));
    if (config.max_depth < 0) throw std::invalid_argument("max depth must not be negative");
}

DeviceFilm make_film(DeviceSession& session, const RenderConfig& config)
{
    check_config(config);
    try {
        return DeviceFilm(session.context(), config.width, config.height, config.film_channels);
    } catch (const cl::Error& error) {
        throw std::runtime_error("allocating the film on " + session.info().name +
                                 " failed: " + describe_cl_error(error));
    }
}

}  // namespace

void choose_traversal(const DeviceInfo& device, const SceneLayout& scene, device::KernelFeatures& features)
{
    // A GPU thread tests one sphere at a time, draws a vertex's numbers
    // before its branches, and keeps the boxes where a CPU runs leaves
    // (kernels/intersect.cl, integrator.cl). A scene without a tree gets a
    // program without traversal code. NVIDIA's own OpenCL takes the PTX of a
    // warp vote (kernels/warp_vote.cl), with which the traversal speculates
    // (docs/design/speculative-traversal.md).
    const bool tree = scene.counts.bvh_node_count > 0;
    const bool nvidia_opencl = device.is_gpu && device.platform.find("NVIDIA") != std::string::npos;
    features.scalar_traversal = device.is_gpu;
    features.draw_all_numbers = device.is_gpu;
    features.bvh_leaf_runs = !device.is_gpu;
    features.bvh = tree;
    features.warp_vote = nvidia_opencl && tree ? 1 : 0;
}

std::string with_development_options(std::string options, const DevelopmentKnobs& knobs)
{
    if (!knobs.cl_options.empty()) options += " " + knobs.cl_options;
    return options;
}

DeviceRenderer::DeviceRenderer(std::shared_ptr<DeviceSession> session, const RenderConfig& config)
    : session_(std::move(session)),
      config_(config),
      film_(make_film(*session_, config)),
      tuner_(session_->info().is_gpu ? kGpuPassSeconds : kCpuPassSeconds)
{
    device::RenderSettings& settings = params_.settings;
    settings.width = config_.width;
    settings.height = config_.height;
    settings.max_depth = config_.max_depth;
    settings.mode = static_cast<int>(config_.mode);
    set_seed(config_.seed);
    active_count_ = static_cast<std::size_t>(config_.width) * static_cast<std::size_t>(config_.height);
    try {
        const device::uint none = ORB_NO_PIXEL;
        active_pixels_ = cl::Buffer(session_->context(), CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, sizeof none,
                                    const_cast<device::uint*>(&none));
    } catch (const cl::Error& error) {
        fail(error, "allocating the list of active pixels");
    }
    if (config_.adaptive) set_every_pixel_active();
    clear_film();
}

void DeviceRenderer::fail(const cl::Error& error, const std::string& what) const
{
    throw std::runtime_error(what + " on " + device().name + " failed: " + describe_cl_error(error));
}

std::string DeviceRenderer::build_options(const SceneLayout& scene) const
{
    return render_program_options(*session_, scene, config_, simd_lanes_);
}

device::KernelFeatures render_features(DeviceSession& session, const SceneLayout& scene, const RenderConfig& config,
                                       int simd_lanes)
{
    // Small scenes live in constant memory (cached, broadcast to a whole
    // warp on GPUs); larger ones in global memory. In constant memory
    // every scene table is one __constant argument of render_pass, and
    // all of them together must fit the constant buffer size (which some
    // drivers apply per buffer, others to the sum).
    const cl::Device& device = session.device();
    const cl_ulong constant_limit = device.getInfo<CL_DEVICE_MAX_CONSTANT_BUFFER_SIZE>();
    const cl_uint constant_args = device.getInfo<CL_DEVICE_MAX_CONSTANT_ARGS>();
    const bool constant_scene = scene_table_bytes(scene.tables) <= constant_limit && kSceneTableCount <= constant_args;
    device::KernelFeatures features;
    features.scene_space = constant_scene ? "__constant" : "__global";
    choose_traversal(session.info(), scene, features);
    features.uniform_lights = scene.uniform_lights;
    // Only the code the scene uses: each material kind's, rough glass's and
    // the environment's cost registers on GPUs whether a scene uses them or
    // not (docs/design/register-caps.md; without the environment's code, 1 M spheres
    // on an H100 render 3.5% faster, 1 k spheres 7%).
    features.material_kinds = scene.material_kinds;
    features.environment = scene.environment.width > 0;
    // No aiming code without casters (4% of an H100's samples/s on
    // simple.scn), nor in direct mode, which counts no light that passed a
    // caster after the first diffuse vertex.
    if (scene.counts.caster_count == 0 || config.mode != IntegratorMode::Global) features.caster_share = 0.0f;
    features.rough_dielectric = scene.rough_dielectric;
    features.sphere_colors = scene.sphere_colors;
    features.sampler_sobol = config.sampler == SamplerKind::Sobol;
    features.film_channels_built = config.film_channels;
    features.lanes = simd_lanes > 0 ? simd_lanes : 1;
    features.active_pixels = config.adaptive;
    return features;
}

std::string render_program_options(DeviceSession& session, const SceneLayout& scene, const RenderConfig& config,
                                   int simd_lanes)
{
    const ProgramOptions options{render_features(session, scene, config, simd_lanes),
                                 nvidia_register_cap(session.device(), scene)};
    return with_development_options(program_options_text(options), config.development);
}

void DeviceRenderer::set_scene(const SceneLayout& scene, const device::CameraParams& camera)
{
    simd_lanes_ = simd_lanes(session_->info(), session_->device(), config_.development);
    // A build from source is timed (and said when slow) up to the end of
    // the kernel's first launch, where PoCL generates its code.
    std::unique_ptr<SlowBuildNotice> building;
    const cl::Program& program = session_->program(build_options(scene), config_.on_slow_kernel_build, &building);
    try {
        if (&program != program_) {
            kernel_ = cl::Kernel(program, "render_pass");
            program_ = &program;
            kernel_prepared_ = false;
            choose_work_sizes();
        }
        upload_scene(session_->context(), session_->queue(), scene.tables, scene_buffers_);
        scene_bytes_ = scene_table_bytes(scene.tables);
        bind_buffers(kernel_, film_, scene_buffers_, 1);
        bind_active_pixels();
    } catch (const cl::Error& error) {
        fail(error, "uploading the scene");
    }
    params_.camera = camera;
    params_.scene = scene.counts;
    params_.environment = scene.environment;
    if (!kernel_prepared_) prepare_kernel();
    if (building) {
        building->finish();
        kernel_build_seconds_ += building->seconds();
    }
}

// One launch of a single work-group that renders no sample (each of its
// pixels adds exact zeros, no centre ray), so that the driver's work done at
// a kernel's first launch (PoCL generates and loads the work-group code
// there, per work-group size: seconds for a program not yet in its cache)
// happens while the renderer is set up, not in the first pass, whose time
// the pass tuner and the render's seconds would otherwise count.
void DeviceRenderer::prepare_kernel()
{
    device::RenderPassParams idle = params_;
    idle.pass.sample_count = 0;
    idle.pass.write_centre_ray = 0;
    try {
        bind_params(kernel_, idle);
        cl::CommandQueue& queue = session_->queue();
        queue.enqueueNDRangeKernel(kernel_, cl::NullRange, local_size_, local_size_);
        queue.finish();
    } catch (const cl::Error& error) {
        fail(error, "preparing the kernel");
    }
    kernel_prepared_ = true;
}

void DeviceRenderer::set_seed(std::uint64_t seed)
{
    config_.seed = seed;
    params_.settings.seed_lo = static_cast<device::uint>(seed & 0xffffffffu);
    params_.settings.seed_hi = static_cast<device::uint>(seed >> 32);
}

void DeviceRenderer::choose_work_sizes()
{
    // One work-item per pixel. GPUs: 16x8 tiles keep a warp on neighbouring
    // pixels, whose paths stay coherent. CPUs (PoCL runs a work-group as a
    // loop on one core): short rows give the scheduler many groups to share.
    // With lanes: one work-item per simd_lanes_ pixels of a row.
    const bool gpu = device().is_gpu;
    size_t lx = gpu ? 16 : 8, ly = gpu ? 8 : 1;
    if (simd_lanes_ > 0) lx = 1, ly = 1;
    if (const std::optional<LocalSize>& knob = config_.development.local_size)  // ORB_LOCAL_SIZE, for tuning
        lx = knob->x, ly = knob->y;
    const size_t max_group = kernel_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(session_->device());
    while (lx * ly > max_group && ly > 1) ly /= 2;
    while (lx * ly > max_group && lx > 1) lx /= 2;
    if (config_.adaptive) {
        // A list, not the image's grid: one dimension, the same work-group size.
        local_size_ = cl::NDRange(lx * ly, 1);
        return;  // the global size follows the list (upload_active_pixels)
    }
    local_size_ = cl::NDRange(lx, ly);
    const auto round_up = [](size_t n, size_t m) { return (n + m - 1) / m * m; };
    const size_t columns = simd_lanes_ > 0 ? (static_cast<size_t>(config_.width) + simd_lanes_ - 1) / simd_lanes_
                                           : static_cast<size_t>(config_.width);
    global_size_ = cl::NDRange(round_up(columns, lx),
                               round_up(static_cast<size_t>(config_.height), ly));
}

std::size_t DeviceRenderer::active_pixel_count() const { return active_count_; }

namespace {

// `list` holding at least `entries` entries, its first `kept` as they were.
void reserve_list(const cl::Context& context, cl::CommandQueue& queue, cl::Buffer& list, std::size_t entries,
                  std::size_t kept)
{
    const std::size_t bytes = std::max<std::size_t>(1, entries) * sizeof(device::uint);
    if (list() && list.getInfo<CL_MEM_SIZE>() >= bytes) return;
    cl::Buffer larger(context, CL_MEM_READ_WRITE, bytes);
    if (list() && kept > 0) queue.enqueueCopyBuffer(list, larger, 0, 0, kept * sizeof(device::uint));
    list = larger;
}

}  // namespace

void DeviceRenderer::set_active_pixels(const std::vector<std::uint32_t>& pixels)
{
    if (!config_.adaptive) throw std::logic_error("set_active_pixels needs a renderer made for adaptive sampling");
    const std::size_t image = static_cast<std::size_t>(config_.width) * static_cast<std::size_t>(config_.height);
    for (std::size_t i = 0; i < pixels.size(); ++i)
        if (pixels[i] >= image || (i > 0 && pixels[i] <= pixels[i - 1]))
            throw std::invalid_argument("active pixels must be ascending indices into the image");
    try {
        reserve_list(session_->context(), session_->queue(), active_pixels_, pixels.size(), 0);
        if (!pixels.empty())
            session_->queue().enqueueWriteBuffer(active_pixels_, CL_TRUE, 0, pixels.size() * sizeof(device::uint),
                                                 pixels.data());
        active_count_ = pixels.size();
        every_pixel_active_ = pixels.size() == image;  // ascending and in the image: 0, 1, ... then
        if (program_) bind_active_pixels();
    } catch (const cl::Error& error) {
        fail(error, "uploading the list of active pixels");
    }
}

void DeviceRenderer::set_every_pixel_active(bool on_device)
{
    if (!config_.adaptive) throw std::logic_error("set_every_pixel_active needs a renderer made for adaptive sampling");
    if (on_device && decides_on_device()) {
        const std::size_t pixels = static_cast<std::size_t>(config_.width) * static_cast<std::size_t>(config_.height);
        try {
            reserve_list(session_->context(), session_->queue(), active_pixels_, pixels, 0);
            decision_->list_every_pixel(session_->queue(), active_pixels_);
            active_count_ = pixels;
            every_pixel_active_ = true;
            if (program_) bind_active_pixels();
        } catch (const cl::Error& error) {
            fail(error, "listing every pixel");
        }
        return;
    }
    std::vector<std::uint32_t> every(static_cast<std::size_t>(config_.width) * static_cast<std::size_t>(config_.height));
    std::iota(every.begin(), every.end(), std::uint32_t{0});
    set_active_pixels(every);
}

std::vector<std::uint32_t> DeviceRenderer::active_pixels()
{
    std::vector<std::uint32_t> pixels(active_count_);
    try {
        if (!pixels.empty())
            session_->queue().enqueueReadBuffer(active_pixels_, CL_TRUE, 0, pixels.size() * sizeof(device::uint),
                                                pixels.data());
    } catch (const cl::Error& error) {
        fail(error, "reading the list of active pixels");
    }
    return pixels;
}

// Binds the list of active pixels to the kernel; with adaptive sampling
// first pads it with ORB_NO_PIXEL to whole work-groups of ORB_LANES entries
// per work-item and sets the launch over it (at least one work-group, which
// prepare_kernel launches). Padding may reallocate the list, so the two go
// together. The padding is filled on the device: the list may have been
// made there (decide()).
void DeviceRenderer::bind_active_pixels()
{
    if (config_.adaptive) pad_active_pixels();
    kernel_.setArg(static_cast<cl_uint>(PassArg::count), active_pixels_);
}

void DeviceRenderer::pad_active_pixels()
{
    const std::size_t lanes = simd_lanes_ > 0 ? static_cast<std::size_t>(simd_lanes_) : 1;
    const std::size_t group = local_size_[0] * local_size_[1];
    const std::size_t count = active_count_;
    const std::size_t items = std::max<std::size_t>(group, (count + lanes - 1) / lanes);
    const std::size_t global = (items + group - 1) / group * group;
    const std::size_t entries = global * lanes;
    cl::CommandQueue& queue = session_->queue();
    reserve_list(session_->context(), queue, active_pixels_, entries, count);
    if (entries > count)
        queue.enqueueFillBuffer(active_pixels_, device::uint{ORB_NO_PIXEL}, count * sizeof(device::uint),
                                (entries - count) * sizeof(device::uint));
    global_size_ = cl::NDRange(global, 1);
}

bool DeviceRenderer::decides_on_device()
{
    if (!decision_checked_) {
        try {
            decision_ = DeviceDecision::make(*session_, config_.width, config_.height);
            if (decision_) decision_->prepare(session_->queue(), film_);
        } catch (const cl::Error& error) {
            fail(error, "preparing adaptive sampling's decision");
        }
        decision_checked_ = true;
    }
    return decision_ != nullptr;
}

std::optional<DecisionOutput> DeviceRenderer::decide(std::uint64_t samples_per_pixel, std::optional<double> noisy_from)
{
    if (noisy_from && !config_.adaptive)
        throw std::logic_error("a decision with a noise threshold needs a renderer made for adaptive sampling");
    if (!decides_on_device()) return std::nullopt;
    try {
        cl::CommandQueue& queue = session_->queue();
        DecisionInput input;
        input.uniform_samples = static_cast<double>(samples_per_pixel);
        input.noisy_from = noisy_from;
        if (noisy_from) {
            reserve_list(session_->context(), queue, next_active_pixels_, active_pixels_.getInfo<CL_MEM_SIZE>() /
                                                                               sizeof(device::uint), 0);
            input.candidates = &active_pixels_;
            input.candidate_count = active_count_;
            input.every_pixel = every_pixel_active_;
            input.still_sampling = &next_active_pixels_;
        }
        const DecisionOutput output = decision_->decide(queue, film_, input);
        if (noisy_from) {
            std::swap(active_pixels_, next_active_pixels_);
            every_pixel_active_ = every_pixel_active_ && output.still_sampling == active_count_;
            active_count_ = output.still_sampling;
            if (program_) bind_active_pixels();
        }
        return output;
    } catch (const cl::Error& error) {
        fail(error, "adaptive sampling's decision");
    }
}

void DeviceRenderer::clear_film()
{
    try {
        film_.clear(session_->queue());
    } catch (const cl::Error& error) {
        fail(error, "clearing the film");
    }
    centre_ray_pending_ = true;
}

void DeviceRenderer::enqueue(std::uint64_t first_sample, int count)
{
    if (count < 0) throw std::invalid_argument("a pass cannot add a negative number of samples");
    if (count == 0) return;
    if (!program_) throw std::logic_error("DeviceRenderer::enqueue before set_scene");
    if (config_.adaptive && active_pixel_count() == 0) return;  // every pixel has stopped: nothing to launch
    if (pending_samples_ == 0) pending_since_ = std::chrono::steady_clock::now();
    try {
        device::PassRange& pass = params_.pass;
        pass.first_sample_lo = static_cast<device::uint>(first_sample & 0xffffffffu);
        pass.first_sample_hi = static_cast<device::uint>(first_sample >> 32);
        pass.sample_count = count;
        pass.write_centre_ray = centre_ray_pending_ ? 1 : 0;
        bind_params(kernel_, params_);
        cl::CommandQueue& queue = session_->queue();
        PassObserver* observer = config_.development.pass_observer.get();
        const PassLaunch launch{*program_, kernel_,      film_,        scene_buffers_,
                                 params_,   active_pixels_, global_size_, local_size_};
        const bool observed = observer && observer->pass_launching(queue, launch);
        queue.enqueueNDRangeKernel(kernel_, cl::NullRange, global_size_, local_size_);
        queue.flush();  // start now: another device may be waiting for its turn
        if (observed) {
            queue.finish();
            observer->pass_finished(queue, launch);
        }
    } catch (const cl::Error& error) {
        fail(error, "a render pass");
    }
    centre_ray_pending_ = false;
    pending_samples_ += count;
}

void DeviceRenderer::wait()
{
    try {
        session_->queue().finish();
    } catch (const cl::Error& error) {
        fail(error, "a render pass");
    }
    if (pending_samples_ > 0) {
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - pending_since_).count();
        tuner_.record(pending_samples_, seconds);
    }
    pending_samples_ = 0;
}

void DeviceRenderer::read_film(Film& film)
{
    try {
        film_.read(session_->queue(), film);
    } catch (const cl::Error& error) {
        fail(error, "reading the film back");
    }
}

FilmArrival DeviceRenderer::read_film_later()
{
    try {
        return film_.read_later(session_->queue(), session_->transfer_queue());
    } catch (const cl::Error& error) {
        fail(error, "reading the film back");
    }
}

void DeviceRenderer::load_film(const Film& film)
{
    try {
        film_.write(session_->queue(), film);
    } catch (const cl::Error& error) {
        fail(error, "uploading the film");
    }
    centre_ray_pending_ = film.samples_per_pixel == 0;
}

int DeviceRenderer::suggested_samples_per_pass() const
{
    // The development knob ORB_PASS_SPP, after the first pass (which still
    // times the device), in place of the tuner's choice.
    if (config_.development.pass_spp && tuner_.seconds_per_sample() > 0) return *config_.development.pass_spp;
    return tuner_.suggested();
}

std::uint64_t DeviceRenderer::device_memory_bytes() const { return film_.bytes() + scene_bytes_; }

}  // namespace orb::render
