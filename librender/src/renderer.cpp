#include "orb/render/renderer.h"

#include <chrono>
#include <cstdlib>
#include <stdexcept>

#include "device_film.h"
#include "opencl_devices.h"
#include "pass_arguments.h"
#include "pass_tuner.h"
#include "program_build.h"
#include "program_source.h"
#include "scene_layout.h"

namespace orb::render {

namespace {

// NVIDIA's compiler gives render_pass about 109 registers, which limits how
// many warps an SM keeps in flight. Capping them at 80 (no spills) measured
// 4.47 -> 4.73 G samples/s at 640x480 and 4.79 -> 5.21 G at 1920x1080 on an
// H100 (docs/performance.md); 64 and below lose again.
std::string nvidia_register_cap(const cl::Device& device)
{
    const std::string extensions = device.getInfo<CL_DEVICE_EXTENSIONS>();
    return extensions.find("cl_nv_compiler_options") != std::string::npos ? " -cl-nv-maxrregcount=80" : "";
}

// Pass lengths aimed at: short on GPUs so no display watchdog fires and
// progress stays smooth; longer on CPUs, where per-pass overhead matters more.
constexpr double kGpuPassSeconds = 0.05;
constexpr double kCpuPassSeconds = 0.25;

[[noreturn]] void rethrow_as_runtime_error(const cl::Error& error, const std::string& what)
{
    throw std::runtime_error(what + ": " + describe_cl_error(error));
}

}  // namespace

struct Renderer::Impl {
    DeviceInfo info;
    RenderConfig config;
    cl::Device device;
    cl::Context context;
    cl::CommandQueue queue;
    cl::Program program;
    cl::Kernel kernel;
    SceneLayout scene;
    SceneBuffers scene_buffers;
    std::unique_ptr<DeviceFilm> film;
    device::RenderPassParams params{};  // all but params.pass is fixed for the render
    cl::NDRange local_size;
    cl::NDRange global_size;
    std::uint64_t spp = 0;
    bool centre_ray_pending = true;  // depth/id of the pixel-centre ray not yet on the film
    PassTuner tuner{kCpuPassSeconds};

    Impl(const Scene& input, const RenderConfig& cfg);
    void choose_work_sizes();
    void fill_fixed_params(const Camera& camera);
};

Renderer::Impl::Impl(const Scene& input, const RenderConfig& cfg) : config(cfg)
{
    if (config.width <= 0 || config.height <= 0)
        throw std::invalid_argument("image size must be positive, got " + std::to_string(config.width) + "x" +
                                    std::to_string(config.height));
    if (config.max_depth < 0) throw std::invalid_argument("max depth must not be negative");
    scene = layout_scene(input, config.use_bvh);
    fill_fixed_params(input.camera);
    info = choose_device(config.device);
    tuner = PassTuner(info.is_gpu ? kGpuPassSeconds : kCpuPassSeconds);
    try {
        device = opencl_device(info.index);
        context = cl::Context(device);
        queue = cl::CommandQueue(context, device);

        // Small scenes live in constant memory (cached, broadcast to a whole
        // warp on GPUs); larger ones in global memory. In constant memory
        // every scene table is one __constant argument of render_pass, and
        // all of them together must fit the constant buffer size (which some
        // drivers apply per buffer, others to the sum).
        const cl_ulong constant_limit = device.getInfo<CL_DEVICE_MAX_CONSTANT_BUFFER_SIZE>();
        const cl_uint constant_args = device.getInfo<CL_DEVICE_MAX_CONSTANT_ARGS>();
        const bool constant_scene =
            scene_table_bytes(scene.tables) <= constant_limit && kSceneTableCount <= constant_args;
        // Unsafe math (reassociation, fast division) gave +8% on an H100 and
        // nothing measurable on PoCL; the analytic tests pass with it.
        std::string options = std::string("-cl-std=CL1.2 -cl-mad-enable -cl-unsafe-math-optimizations") +
                              " -DORB_SCENE_SPACE=" + (constant_scene ? "__constant" : "__global") +
                              (info.is_gpu ? " -DORB_INTERSECT_SCALAR=1" : "") +
                              // A scene without a tree gets a program without traversal code.
                              (scene.counts.bvh_node_count > 0 ? " -DORB_BVH=1" : " -DORB_BVH=0") +
                              (scene.uniform_lights ? " -DORB_UNIFORM_LIGHTS=1" : "") +
                              nvidia_register_cap(device);
        if (const char* extra = std::getenv("ORB_CL_OPTIONS")) options += std::string(" ") + extra;  // development knob
        program = build_program(context, device, program_source(config.kernel_dir), options,
                                config.use_binary_cache)
                      .program;
        kernel = cl::Kernel(program, "render_pass");

        scene_buffers = upload_scene(context, scene.tables);
        film = std::make_unique<DeviceFilm>(context, config.width, config.height);
        film->clear(queue);
        choose_work_sizes();
        bind_buffers(kernel, *film, scene_buffers);
    } catch (const cl::Error& error) {
        rethrow_as_runtime_error(error, "OpenCL setup on " + info.name + " failed");
    }
}

void Renderer::Impl::choose_work_sizes()
{
    // One work-item per pixel. GPUs: 16x8 tiles keep a warp on neighbouring
    // pixels, whose paths stay coherent. CPUs (PoCL runs a work-group as a
    // loop on one core): short rows give the scheduler many groups to share.
    size_t lx = info.is_gpu ? 16 : 8, ly = info.is_gpu ? 8 : 1;
    if (const char* env = std::getenv("ORB_LOCAL_SIZE")) {  // development knob for tuning, "XxY"
        unsigned ex = 0, ey = 0;
        if (std::sscanf(env, "%ux%u", &ex, &ey) == 2 && ex > 0 && ey > 0) lx = ex, ly = ey;
    }
    const size_t max_group = kernel.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(device);
    while (lx * ly > max_group && ly > 1) ly /= 2;
    while (lx * ly > max_group && lx > 1) lx /= 2;
    local_size = cl::NDRange(lx, ly);
    const auto round_up = [](size_t n, size_t m) { return (n + m - 1) / m * m; };
    global_size = cl::NDRange(round_up(static_cast<size_t>(config.width), lx),
                              round_up(static_cast<size_t>(config.height), ly));
}

void Renderer::Impl::fill_fixed_params(const Camera& camera)
{
    params.camera = layout_camera(camera, config.width, config.height);
    params.scene = scene.counts;
    params.environment = scene.environment;
    device::RenderSettings& settings = params.settings;
    settings.width = config.width;
    settings.height = config.height;
    settings.max_depth = config.max_depth;
    settings.mode = static_cast<int>(config.mode);
    settings.seed_lo = static_cast<device::uint>(config.seed & 0xffffffffu);
    settings.seed_hi = static_cast<device::uint>(config.seed >> 32);
}

Renderer::Renderer(const Scene& scene, const RenderConfig& config) : impl_(std::make_unique<Impl>(scene, config)) {}
Renderer::~Renderer() = default;

const DeviceInfo& Renderer::device() const { return impl_->info; }
const RenderConfig& Renderer::config() const { return impl_->config; }
int Renderer::suggested_samples_per_pass() const { return impl_->tuner.suggested(); }
std::uint64_t Renderer::samples_per_pixel() const { return impl_->spp; }

void Renderer::render_pass(int samples)
{
    if (samples < 0) throw std::invalid_argument("a pass cannot add a negative number of samples");
    if (samples == 0) return;
    Impl& r = *impl_;
    const auto start = std::chrono::steady_clock::now();
    try {
        device::PassRange& pass = r.params.pass;
        pass.first_sample_lo = static_cast<device::uint>(r.spp & 0xffffffffu);
        pass.first_sample_hi = static_cast<device::uint>(r.spp >> 32);
        pass.sample_count = samples;
        pass.write_centre_ray = r.centre_ray_pending ? 1 : 0;
        bind_params(r.kernel, r.params);
        r.queue.enqueueNDRangeKernel(r.kernel, cl::NullRange, r.global_size, r.local_size);
        r.queue.finish();
    } catch (const cl::Error& error) {
        rethrow_as_runtime_error(error, "a render pass on " + r.info.name + " failed");
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.spp += static_cast<std::uint64_t>(samples);
    r.centre_ray_pending = false;
    r.tuner.record(samples, seconds);
}

Film Renderer::read_film() const
{
    try {
        Film film = impl_->film->read(impl_->queue);
        film.samples_per_pixel = impl_->spp;
        return film;
    } catch (const cl::Error& error) {
        rethrow_as_runtime_error(error, "reading the film back from " + impl_->info.name + " failed");
    }
}

void Renderer::load_film(const Film& film)
{
    try {
        impl_->film->write(impl_->queue, film);
    } catch (const cl::Error& error) {
        rethrow_as_runtime_error(error, "uploading the film to " + impl_->info.name + " failed");
    }
    impl_->spp = film.samples_per_pixel;
    impl_->centre_ray_pending = film.samples_per_pixel == 0;
}

std::uint64_t Renderer::device_memory_bytes() const
{
    const Impl& r = *impl_;
    return r.film->bytes() + scene_table_bytes(r.scene.tables);
}

}  // namespace orb::render
