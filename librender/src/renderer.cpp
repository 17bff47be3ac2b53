#include "orb/render/renderer.h"

#include <chrono>
#include <cstdlib>
#include <stdexcept>

#include "device_film.h"
#include "opencl_devices.h"
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

template <typename T>
cl::Buffer read_only_buffer(const cl::Context& context, const std::vector<T>& data)
{
    // OpenCL has no empty buffers; a scene without spheres or lights still needs one.
    static const T placeholder{};
    const void* bytes = data.empty() ? static_cast<const void*>(&placeholder) : data.data();
    const size_t size = std::max<size_t>(1, data.size()) * sizeof(T);
    return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, size, const_cast<void*>(bytes));
}

cl_float4 to_cl(const Float4& v) { return {{v[0], v[1], v[2], v[3]}}; }

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
    CameraLayout camera;
    cl::Buffer packets, records, lights;
    std::unique_ptr<DeviceFilm> film;
    cl::NDRange local_size;
    cl::NDRange global_size;
    std::uint64_t spp = 0;
    bool centre_ray_pending = true;  // depth/id of the pixel-centre ray not yet on the film
    PassTuner tuner{kCpuPassSeconds};
    cl_uint arg_sample_start = 0;  // kernel argument positions of the per-pass values
    cl_uint arg_write_centre = 0;

    Impl(const Scene& input, const RenderConfig& cfg);
    void choose_work_sizes();
    void set_fixed_arguments();
};

Renderer::Impl::Impl(const Scene& input, const RenderConfig& cfg) : config(cfg)
{
    if (config.width <= 0 || config.height <= 0)
        throw std::invalid_argument("image size must be positive, got " + std::to_string(config.width) + "x" +
                                    std::to_string(config.height));
    if (config.max_depth < 0) throw std::invalid_argument("max depth must not be negative");
    scene = layout_scene(input);
    camera = layout_camera(input.camera, config.width, config.height);
    info = choose_device(config.device);
    tuner = PassTuner(info.is_gpu ? kGpuPassSeconds : kCpuPassSeconds);
    try {
        device = opencl_device(info.index);
        context = cl::Context(device);
        queue = cl::CommandQueue(context, device);

        // Small scenes live in constant memory (cached, broadcast to a whole
        // warp on GPUs); larger ones in global memory.
        const cl_ulong constant_limit = device.getInfo<CL_DEVICE_MAX_CONSTANT_BUFFER_SIZE>();
        const cl_uint constant_args = device.getInfo<CL_DEVICE_MAX_CONSTANT_ARGS>();
        const bool constant_scene = scene.bytes() + 64 <= constant_limit && constant_args >= 3;
        // Unsafe math (reassociation, fast division) gave +8% on an H100 and
        // nothing measurable on PoCL; the analytic tests pass with it.
        std::string options = std::string("-cl-std=CL1.2 -cl-mad-enable -cl-unsafe-math-optimizations") +
                              " -DORB_SCENE_SPACE=" + (constant_scene ? "__constant" : "__global") +
                              (info.is_gpu ? " -DORB_INTERSECT_SCALAR=1" : "") +
                              nvidia_register_cap(device);
        if (const char* extra = std::getenv("ORB_CL_OPTIONS")) options += std::string(" ") + extra;  // development knob
        program = build_program(context, device, program_source(config.kernel_dir), options,
                                config.use_binary_cache)
                      .program;
        kernel = cl::Kernel(program, "render_pass");

        packets = read_only_buffer(context, scene.packets);
        records = read_only_buffer(context, scene.records);
        lights = read_only_buffer(context, scene.lights);
        film = std::make_unique<DeviceFilm>(context, config.width, config.height);
        film->clear(queue);
        choose_work_sizes();
        set_fixed_arguments();
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

void Renderer::Impl::set_fixed_arguments()
{
    cl_uint arg = 0;
    for (const cl::Buffer& buffer : film->buffers()) kernel.setArg(arg++, buffer);
    kernel.setArg(arg++, packets);
    kernel.setArg(arg++, static_cast<cl_int>(scene.packet_count));
    kernel.setArg(arg++, static_cast<cl_int>(scene.sphere_count));
    kernel.setArg(arg++, records);
    kernel.setArg(arg++, lights);
    kernel.setArg(arg++, static_cast<cl_int>(scene.lights.size()));
    kernel.setArg(arg++, to_cl(camera.origin));
    kernel.setArg(arg++, to_cl(camera.right));
    kernel.setArg(arg++, to_cl(camera.up));
    kernel.setArg(arg++, to_cl(camera.forward));
    kernel.setArg(arg++, to_cl(camera.lens));
    kernel.setArg(arg++, static_cast<cl_int>(config.width));
    kernel.setArg(arg++, static_cast<cl_int>(config.height));
    arg_sample_start = arg;  // sample start (lo, hi) and count change per pass
    arg += 3;
    kernel.setArg(arg++, static_cast<cl_uint>(config.seed & 0xffffffffu));
    kernel.setArg(arg++, static_cast<cl_uint>(config.seed >> 32));
    kernel.setArg(arg++, static_cast<cl_int>(config.max_depth));
    kernel.setArg(arg++, static_cast<cl_int>(config.mode == IntegratorMode::Direct ? 1 : 0));
    arg_write_centre = arg;  // per pass
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
        r.kernel.setArg(r.arg_sample_start + 0, static_cast<cl_uint>(r.spp & 0xffffffffu));
        r.kernel.setArg(r.arg_sample_start + 1, static_cast<cl_uint>(r.spp >> 32));
        r.kernel.setArg(r.arg_sample_start + 2, static_cast<cl_int>(samples));
        r.kernel.setArg(r.arg_write_centre, static_cast<cl_int>(r.centre_ray_pending ? 1 : 0));
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
    const auto buffer_bytes = [](const cl::Buffer& b) { return static_cast<std::uint64_t>(b.getInfo<CL_MEM_SIZE>()); };
    return r.film->bytes() + buffer_bytes(r.packets) + buffer_bytes(r.records) + buffer_bytes(r.lights);
}

}  // namespace orb::render
