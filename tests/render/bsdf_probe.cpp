#define CL_HPP_ENABLE_EXCEPTIONS
#include "bsdf_probe.h"

#include <CL/opencl.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

#include "orb/render/device.h"
#include "program_build.h"
#include "program_source.h"
#include "opencl_devices.h"

namespace orb::render::test {
namespace {

// Appended to the whole Orb program (so the BSDFs are exactly the ones
// render_pass uses). The shading frame is n = +z at the origin; `wo_outside`
// carries wo in xyz and the `outside` flag in w. Sampling and densities go
// through the continuation's mixture (caustic_casters.cl), which with no
// casters is the BSDF's own sampling and pdf.
constexpr const char* kProbeKernels = R"CL(
inline SceneView probe_scene(__constant CasterRecord* casters, int caster_count)
{
    SceneView scene;
    scene.casters = casters;
    scene.caster_count = caster_count;
    return scene;
}

__kernel void probe_sample(__constant MaterialRecord* material, __constant CasterRecord* casters, int caster_count,
                           float4 wo_outside, uint2 seed, __global float4* direction, __global float4* weight,
                           __global float4* check)
{
    const uint i = get_global_id(0);
    const SceneView scene = probe_scene(casters, caster_count);
    const Bsdf b = load_bsdf(material);
    const float3 p = (float3)(0.0f), n = (float3)(0.0f, 0.0f, 1.0f);
    const bool outside = wo_outside.w > 0.5f;
    const Rand5 r = rng_block(i, 0, 0u, seed);
    float choice = r.u4;
    const BsdfSample s = sample_continuation(&scene, &b, p, wo_outside.xyz, n, outside, r.u2, r.u3, &choice);
    float bsdf_pdf;
    const float3 f_cos = bsdf_eval(&b, wo_outside.xyz, s.wi, n, outside, &bsdf_pdf);
    // A direction was returned: one with a density (its weight may be 0:
    // an aimed direction below the surface), or a delta lobe's.
    const bool carries = s.weight.x + s.weight.y + s.weight.z > 0.0f;
    direction[i] = (float4)(s.wi, s.delta ? (carries ? 2.0f : 0.0f) : (s.pdf > 0.0f ? 1.0f : 0.0f));
    weight[i] = (float4)(s.weight, s.pdf);
    check[i] = (float4)(f_cos, continuation_pdf(&scene, p, bsdf_pdf, s.wi));
}

__kernel void probe_eval(__constant MaterialRecord* material, __constant CasterRecord* casters, int caster_count,
                         int outside, __global const float4* wo, __global const float4* wi, __global float4* out)
{
    const uint i = get_global_id(0);
    const SceneView scene = probe_scene(casters, caster_count);
    const Bsdf b = load_bsdf(material);
    const float3 p = (float3)(0.0f), n = (float3)(0.0f, 0.0f, 1.0f);
    float pdf;
    const float3 f_cos = bsdf_eval(&b, wo[i].xyz, wi[i].xyz, n, outside != 0, &pdf);
    out[i] = (float4)(f_cos, continuation_pdf(&scene, p, pdf, wi[i].xyz));
}
)CL";

// The casters as a buffer (one placeholder record when there are none: OpenCL has no empty buffers).
cl::Buffer caster_buffer(const cl::Context& context, const std::vector<device::CasterRecord>& casters)
{
    std::vector<device::CasterRecord> records = casters;
    if (records.empty()) records.push_back({});
    return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, records.size() * sizeof(records[0]),
                      records.data());
}

cl_float4 wo_outside(const Dir& wo, bool outside)
{
    cl_float4 v;
    v.s[0] = static_cast<float>(wo[0]);
    v.s[1] = static_cast<float>(wo[1]);
    v.s[2] = static_cast<float>(wo[2]);
    v.s[3] = outside ? 1.0f : 0.0f;
    return v;
}

}  // namespace

struct BsdfProbe::Impl {
    cl::Context context;
    cl::Device device;
    cl::CommandQueue queue;
    cl::Program program;
};

BsdfProbe::BsdfProbe() : impl_(std::make_unique<Impl>())
{
    const DeviceInfo info = choose_device("");
    impl_->device = opencl_device(info.index);
    impl_->context = cl::Context(impl_->device);
    impl_->queue = cl::CommandQueue(impl_->context, impl_->device);
    impl_->program = cl::Program(impl_->context, program_source("") + kProbeKernels);
    try {
        // The options render_pass is built with, so the probe sees the same arithmetic.
        impl_->program.build({impl_->device}, program_options_text(ProgramOptions{}).c_str());
    } catch (const cl::Error&) {
        throw std::runtime_error("probe kernels failed to build: " +
                                 impl_->program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(impl_->device));
    }
}

BsdfProbe::~BsdfProbe() = default;

std::vector<ProbeSample> BsdfProbe::sample(const device::MaterialRecord& material, const Dir& wo, bool outside,
                                           std::size_t count, unsigned seed,
                                           const std::vector<device::CasterRecord>& casters)
{
    cl::Buffer record(impl_->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof material,
                      const_cast<device::MaterialRecord*>(&material));
    cl::Buffer direction(impl_->context, CL_MEM_WRITE_ONLY, count * sizeof(cl_float4));
    cl::Buffer weight(impl_->context, CL_MEM_WRITE_ONLY, count * sizeof(cl_float4));
    cl::Buffer check(impl_->context, CL_MEM_WRITE_ONLY, count * sizeof(cl_float4));
    const cl::Buffer caster_records = caster_buffer(impl_->context, casters);
    cl::Kernel kernel(impl_->program, "probe_sample");
    kernel.setArg(0, record);
    kernel.setArg(1, caster_records);
    kernel.setArg(2, cl_int(casters.size()));
    kernel.setArg(3, wo_outside(wo, outside));
    cl_uint2 key;
    key.s[0] = seed;
    key.s[1] = 0x5eedu;
    kernel.setArg(4, key);
    kernel.setArg(5, direction);
    kernel.setArg(6, weight);
    kernel.setArg(7, check);
    impl_->queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(count));
    std::vector<cl_float4> d(count), w(count), c(count);
    impl_->queue.enqueueReadBuffer(direction, CL_TRUE, 0, count * sizeof(cl_float4), d.data());
    impl_->queue.enqueueReadBuffer(weight, CL_TRUE, 0, count * sizeof(cl_float4), w.data());
    impl_->queue.enqueueReadBuffer(check, CL_TRUE, 0, count * sizeof(cl_float4), c.data());
    std::vector<ProbeSample> out(count);
    for (std::size_t i = 0; i < count; ++i) {
        ProbeSample& s = out[i];
        s.wi = {d[i].s[0], d[i].s[1], d[i].s[2]};
        s.valid = d[i].s[3] > 0.5f;
        s.delta = d[i].s[3] > 1.5f;
        s.weight = {w[i].s[0], w[i].s[1], w[i].s[2]};
        s.pdf = w[i].s[3];
        s.eval_f_cos = {c[i].s[0], c[i].s[1], c[i].s[2]};
        s.eval_pdf = c[i].s[3];
    }
    return out;
}

std::vector<ProbeEval> BsdfProbe::eval(const device::MaterialRecord& material, bool outside, const std::vector<Dir>& wo,
                                       const std::vector<Dir>& wi, const std::vector<device::CasterRecord>& casters)
{
    const std::size_t count = wi.size();
    if (wo.size() != count) throw std::invalid_argument("BsdfProbe::eval: as many wo as wi");
    std::vector<ProbeEval> out(count);
    if (count == 0) return out;
    std::vector<cl_float4> wo_in(count), wi_in(count);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t k = 0; k < 3; ++k) {
            wo_in[i].s[k] = static_cast<float>(wo[i][k]);
            wi_in[i].s[k] = static_cast<float>(wi[i][k]);
        }
    cl::Buffer record(impl_->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof material,
                      const_cast<device::MaterialRecord*>(&material));
    cl::Buffer wo_buffer(impl_->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, count * sizeof(cl_float4),
                         wo_in.data());
    cl::Buffer wi_buffer(impl_->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, count * sizeof(cl_float4),
                         wi_in.data());
    cl::Buffer result(impl_->context, CL_MEM_WRITE_ONLY, count * sizeof(cl_float4));
    const cl::Buffer caster_records = caster_buffer(impl_->context, casters);
    cl::Kernel kernel(impl_->program, "probe_eval");
    kernel.setArg(0, record);
    kernel.setArg(1, caster_records);
    kernel.setArg(2, cl_int(casters.size()));
    kernel.setArg(3, cl_int(outside ? 1 : 0));
    kernel.setArg(4, wo_buffer);
    kernel.setArg(5, wi_buffer);
    kernel.setArg(6, result);
    impl_->queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(count));
    std::vector<cl_float4> r(count);
    impl_->queue.enqueueReadBuffer(result, CL_TRUE, 0, count * sizeof(cl_float4), r.data());
    for (std::size_t i = 0; i < count; ++i) out[i] = {{r[i].s[0], r[i].s[1], r[i].s[2]}, r[i].s[3]};
    return out;
}

std::vector<ProbeEval> BsdfProbe::eval(const device::MaterialRecord& material, bool outside, const Dir& wo,
                                       const std::vector<Dir>& wi, const std::vector<device::CasterRecord>& casters)
{
    return eval(material, outside, std::vector<Dir>(wi.size(), wo), wi, casters);
}

device::MaterialRecord material_record(device::MaterialKind kind, std::array<float, 3> color, float roughness,
                                       float metallic, float ior)
{
    device::MaterialRecord record{};
    record.color = {color[0], color[1], color[2], 0.0f};
    record.emission = {0.0f, 0.0f, 0.0f, 0.0f};
    record.ior = ior;
    record.kind = static_cast<int>(kind);
    record.roughness = roughness;
    record.metallic = metallic;
    return record;
}

Dir direction_at(double cos_theta)
{
    return {std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta)), 0.0, cos_theta};
}

}  // namespace orb::render::test
