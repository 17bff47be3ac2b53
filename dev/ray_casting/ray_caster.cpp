#include "ray_caster.h"

#include <chrono>
#include <cstring>
#include <stdexcept>
#include <string_view>

#include "device_renderer.h"
#include "program_build.h"

namespace orb::kernels::embedded_sources {
// dev/ray_casting/trace_rays.cl, embedded by dev/CMakeLists.txt.
extern const std::string_view dev_trace_rays_cl;
}  // namespace orb::kernels::embedded_sources

namespace orb::render {
namespace {

constexpr cl_uint kRaysArg = static_cast<cl_uint>(PassArg::count);
constexpr cl_uint kResultsArg = kRaysArg + 1;
constexpr cl_uint kRayCountArg = kRaysArg + 2;
constexpr cl_uint kShadowArg = kRaysArg + 3;
constexpr cl_uint kTrailingArgs = 4;

std::string trace_options(const DeviceInfo& info, const SceneLayout& scene, const std::string& extra)
{
    ProgramOptions program;
    program.features.scene_space = "__global";
    program.features.trace_kernel = true;
    choose_traversal(info, scene, program.features);
    std::string options = program_options_text(program);
    if (!extra.empty()) options += " " + extra;
    return options;
}

// The product's kernels (from the session: embedded, or its kernel folder)
// followed by trace_rays.cl, which uses what they define.
std::string trace_source(const DeviceSession& session)
{
    return session.source() + "#line 1 \"trace_rays.cl\"\n" +
           std::string(kernels::embedded_sources::dev_trace_rays_cl) + "\n";
}

}  // namespace

RayCaster::RayCaster(std::shared_ptr<DeviceSession> session, const SceneLayout& scene, const std::string& extra_options)
    : session_(std::move(session)), film_(session_->context(), 1, 1)
{
    const SessionOptions& options = session_->options();
    program_ = build_program(session_->context(), session_->device(), trace_source(*session_),
                             trace_options(session_->info(), scene, extra_options), options.use_binary_cache,
                             options.show_build_log)
                   .program;
    try {
        kernel_ = cl::Kernel(program_, "trace_rays");
        scene_buffers_ = upload_scene(session_->context(), scene.tables);
        bind_buffers(kernel_, film_, scene_buffers_, kTrailingArgs);
        device::RenderPassParams params{};
        params.scene = scene.counts;
        params.environment = scene.environment;
        bind_params(kernel_, params);
    } catch (const cl::Error& error) {
        throw std::runtime_error("setting up trace_rays on " + session_->info().name +
                                 " failed: " + describe_cl_error(error));
    }
}

void RayCaster::load(const std::vector<CastRay>& rays)
{
    if (rays.empty()) throw std::invalid_argument("no rays to cast");
    try {
        rays_ = cl::Buffer(session_->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, rays.size() * sizeof(CastRay),
                           const_cast<CastRay*>(rays.data()));
        results_ = cl::Buffer(session_->context(), CL_MEM_WRITE_ONLY, rays.size() * 2 * sizeof(cl_int));
        loaded_ = static_cast<int>(rays.size());
        kernel_.setArg(kRaysArg, rays_);
        kernel_.setArg(kResultsArg, results_);
        kernel_.setArg(kRayCountArg, loaded_);
    } catch (const cl::Error& error) {
        throw std::runtime_error("uploading rays to " + session_->info().name + " failed: " + describe_cl_error(error));
    }
}

void RayCaster::launch(bool shadow_rays)
{
    constexpr std::size_t kGroup = 128;  // four warps on NVIDIA; PoCL's scheduler splits the rest
    const std::size_t global = (static_cast<std::size_t>(loaded_) + kGroup - 1) / kGroup * kGroup;
    kernel_.setArg(kShadowArg, shadow_rays ? 1 : 0);
    session_->queue().enqueueNDRangeKernel(kernel_, cl::NullRange, cl::NDRange(global), cl::NDRange(kGroup));
}

double RayCaster::cast_loaded(bool shadow_rays, int times)
{
    try {
        session_->queue().finish();
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < times; ++i) launch(shadow_rays);
        session_->queue().finish();
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } catch (const cl::Error& error) {
        throw std::runtime_error("casting rays on " + session_->info().name + " failed: " + describe_cl_error(error));
    }
}

std::vector<cl_int> RayCaster::cast_and_read(const std::vector<CastRay>& rays, bool shadow_rays)
{
    load(rays);
    cast_loaded(shadow_rays, 1);
    std::vector<cl_int> raw(2 * rays.size());
    try {
        session_->queue().enqueueReadBuffer(results_, CL_TRUE, 0, raw.size() * sizeof(cl_int), raw.data());
    } catch (const cl::Error& error) {
        throw std::runtime_error("reading ray results from " + session_->info().name +
                                 " failed: " + describe_cl_error(error));
    }
    return raw;
}

std::vector<CastHit> RayCaster::closest(const std::vector<CastRay>& rays)
{
    const std::vector<cl_int> raw = cast_and_read(rays, false);
    std::vector<CastHit> hits(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        hits[i].sphere = raw[2 * i];
        std::memcpy(&hits[i].t, &raw[2 * i + 1], sizeof(float));
    }
    return hits;
}

std::vector<bool> RayCaster::visible(const std::vector<CastRay>& rays)
{
    const std::vector<cl_int> raw = cast_and_read(rays, true);
    std::vector<bool> result(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) result[i] = raw[2 * i] != 0;
    return result;
}

}  // namespace orb::render
