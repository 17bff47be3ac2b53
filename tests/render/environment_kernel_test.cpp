// kernels/environment.cl on the device (PoCL here), through probe kernels
// compiled with the real program: the directions sample_environment draws
// follow the texels' probabilities and are uniform in solid angle inside a
// texel (a chi-squared test over quarter texels, binned by the documented
// orientation computed independently here, in double), the density it
// reports is the one environment_lookup gives for the same direction, and
// known directions land in the texels docs/scene-format.md says they do.
#define CL_HPP_ENABLE_EXCEPTIONS
#include <CL/opencl.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "chi2.h"
#include "environment_distribution.h"
#include "environment_layout.h"
#include "orb/tables/kernel_features.h"
#include "orb/render/device.h"
#include "program_source.h"
#include "opencl_devices.h"

namespace orb::render::test {
namespace {

constexpr const char* kProbes = R"(
__kernel void probe_sample(__global const EnvironmentTexel* texels, __global const EnvironmentCdf* cdf,
                           EnvironmentParams environment, __global const float2* uv, __global float4* direction,
                           __global float4* sampled, __global float4* looked_up, __global int* looked_up_index)
{
    const int i = get_global_id(0);
    SceneView scene;
    scene.environment_texels = texels;
    scene.environment_cdf = cdf;
    scene.environment = environment;
    float4 texel;
    const float3 d = sample_environment(&scene, uv[i].x, uv[i].y, &texel);
    direction[i] = (float4)(d, 0.0f);
    sampled[i] = texel;
    looked_up[i] = environment_lookup(&scene, d);
    looked_up_index[i] = environment_texel_of(&scene, d);
}

__kernel void probe_lookup(__global const EnvironmentTexel* texels, __global const EnvironmentCdf* cdf,
                           EnvironmentParams environment, __global const float4* direction, __global int* index)
{
    const int i = get_global_id(0);
    SceneView scene;
    scene.environment_texels = texels;
    scene.environment_cdf = cdf;
    scene.environment = environment;
    index[i] = environment_texel_of(&scene, direction[i].xyz);
}
)";

struct Probe {
    cl::Device device;
    cl::Context context;
    cl::CommandQueue queue;
    cl::Program program;
};

Probe build_probe() {
    const DeviceInfo info = choose_device("");
    Probe p;
    p.device = opencl_device(info.index);
    p.context = cl::Context(p.device);
    p.queue = cl::CommandQueue(p.context, p.device);
    p.program = cl::Program(p.context, program_source("") + kProbes);
    try {
        device::KernelFeatures features;
        features.scene_space = "__global";
        p.program.build({p.device}, ("-cl-std=CL1.2 " + device::kernel_feature_options(features)).c_str());
    } catch (const cl::Error&) {
        throw std::runtime_error(p.program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(p.device));
    }
    return p;
}

template <typename T>
cl::Buffer input(const Probe& p, const std::vector<T>& data) {
    return cl::Buffer(p.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, data.size() * sizeof(T),
                      const_cast<T*>(data.data()));
}

// The documented orientation, in double: the map's frame is the world
// turned about +y by `rotation_deg`; there u = 1/2 + atan2(z, x) / 2 pi and
// v = acos(y) / pi (from the top row). Returns the column and row as reals.
std::pair<double, double> map_position(double x, double y, double z, double rotation_deg, int width, int height) {
    const double a = rotation_deg * std::numbers::pi / 180.0;
    const double mx = std::cos(a) * x - std::sin(a) * z, mz = std::sin(a) * x + std::cos(a) * z;
    const double length = std::sqrt(x * x + y * y + z * z);
    const double u = 0.5 + std::atan2(mz, mx) / (2.0 * std::numbers::pi);
    const double v = std::acos(std::clamp(y / length, -1.0, 1.0)) / std::numbers::pi;
    return {u * width, v * height};
}

EnvironmentLayout map_layout(int width, int height, double rotation_deg, unsigned seed) {
    auto image = std::make_shared<EnvironmentImage>();
    image->width = width;
    image->height = height;
    std::mt19937 rng(seed);
    std::exponential_distribution<float> radiance(1.0f);
    for (int i = 0; i < width * height * 3; ++i) image->rgb.push_back(radiance(rng));
    for (int c = 0; c < 3; ++c) image->rgb[std::size_t(3 * (width + 2) + c)] = 0.0f;  // a black texel
    Environment environment;
    environment.kind = EnvironmentKind::Map;
    environment.map = "test.exr";
    environment.intensity = 2.0;
    environment.rotation_deg = rotation_deg;
    environment.image = image;
    return layout_environment(environment);
}

TEST(EnvironmentKernel, SamplesFollowTheDistributionAndAgreeWithLookups) {
    const int width = 12, height = 6;
    const double rotation_deg = 30.0;
    const EnvironmentLayout layout = map_layout(width, height, rotation_deg, 9);
    ASSERT_TRUE(layout.emits);
    const Probe p = build_probe();

    const int n = 400'000;
    std::vector<cl_float2> uv(n);
    std::mt19937 rng(31);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (cl_float2& x : uv) x = {{uniform(rng), uniform(rng)}};
    cl::Buffer direction(p.context, CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    cl::Buffer sampled(p.context, CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    cl::Buffer looked_up(p.context, CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    cl::Buffer looked_up_index(p.context, CL_MEM_WRITE_ONLY, n * sizeof(cl_int));
    // Kept alive until the kernel has run: a kernel argument does not own its buffer.
    const cl::Buffer texels = input(p, layout.texels), cdf = input(p, layout.cdf), uv_buffer = input(p, uv);
    cl::Kernel kernel(p.program, "probe_sample");
    kernel.setArg(0, texels);
    kernel.setArg(1, cdf);
    kernel.setArg(2, sizeof layout.params, &layout.params);
    kernel.setArg(3, uv_buffer);
    kernel.setArg(4, direction);
    kernel.setArg(5, sampled);
    kernel.setArg(6, looked_up);
    kernel.setArg(7, looked_up_index);
    cl::CommandQueue queue = p.queue;
    queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(n));
    std::vector<cl_float4> d(n), s(n), l(n);
    std::vector<cl_int> index(n);
    queue.enqueueReadBuffer(direction, CL_TRUE, 0, n * sizeof(cl_float4), d.data());
    queue.enqueueReadBuffer(sampled, CL_TRUE, 0, n * sizeof(cl_float4), s.data());
    queue.enqueueReadBuffer(looked_up, CL_TRUE, 0, n * sizeof(cl_float4), l.data());
    queue.enqueueReadBuffer(looked_up_index, CL_TRUE, 0, n * sizeof(cl_int), index.data());

    // Quarter texels: halves in phi and halves in cos(theta) have equal solid angles.
    std::vector<double> observed(std::size_t(width * height * 4), 0.0);
    int disagreements = 0, off_unit = 0;
    for (int i = 0; i < n; ++i) {
        const double x = d[i].s[0], y = d[i].s[1], z = d[i].s[2];
        off_unit += std::fabs(std::sqrt(x * x + y * y + z * z) - 1.0) > 1e-5;
        const auto [column_real, row_real] = map_position(x, y, z, rotation_deg, width, height);
        const int column = std::clamp(int(column_real), 0, width - 1), row = std::clamp(int(row_real), 0, height - 1);
        const double cos_top = std::cos(std::numbers::pi * row / height), cos_bottom = std::cos(std::numbers::pi * (row + 1) / height);
        const int lower_half = y / std::sqrt(x * x + y * y + z * z) < 0.5 * (cos_top + cos_bottom);
        const int right_half = column_real - column >= 0.5;
        observed[std::size_t(4 * (row * width + column) + 2 * lower_half + right_half)] += 1;
        // The texel sampled is the one a lookup of its direction finds, and
        // both report the same radiance and density (rare float ties on a
        // texel's border aside).
        const bool same = index[i] == row * width + column && s[i].s[0] == l[i].s[0] && s[i].s[3] == l[i].s[3];
        disagreements += !same;
    }
    EXPECT_EQ(off_unit, 0);
    EXPECT_LE(disagreements, n / 10000) << "samples whose texel, radiance or density differ between sampling and lookup";

    const EnvironmentDistribution distribution = [&] {
        std::vector<double> weights(std::size_t(width * height));
        for (std::size_t t = 0; t < weights.size(); ++t)
            weights[t] = (double(layout.texels[t].radiance_pdf.x) + layout.texels[t].radiance_pdf.y +
                          layout.texels[t].radiance_pdf.z) / 3.0;
        return build_environment_distribution(weights, width, height);
    }();
    std::vector<double> expected(observed.size());
    for (std::size_t t = 0; t < distribution.probability.size(); ++t) {
        // The density the device stores is the realised probability over the solid angle.
        EXPECT_NEAR(layout.texels[t].radiance_pdf.w,
                    distribution.probability[t] / environment_texel_solid_angle(int(t) / width, width, height),
                    1e-6 * layout.texels[t].radiance_pdf.w);
        for (int q = 0; q < 4; ++q) expected[4 * t + std::size_t(q)] = distribution.probability[t] * n / 4.0;
    }
    const Chi2Result result = pearson_chi2(observed, expected);
    EXPECT_TRUE(result.problem.empty()) << result.problem;
    EXPECT_GT(result.p_value, 0.01) << "chi2 " << result.statistic << " with " << result.dof << " dof";
}

// Directions and the texel (column, row) the documentation puts them in, on
// an 8 x 4 map.
struct KnownDirection {
    cl_float4 direction;
    double rotation_deg;
    int column, row;
};

TEST(EnvironmentKernel, KnownDirectionsLandInTheDocumentedTexels) {
    const int width = 8, height = 4;
    const std::vector<KnownDirection> cases{
        {{{1.0f, 0.2f, 0.05f, 0}}, 0, 4, 1},     // +x, a little above the horizon: the centre column, upper half
        {{{0.05f, 0.2f, 1.0f, 0}}, 0, 5, 1},     // +z: three quarters across (u just below 0.75)
        {{{0.05f, 0.2f, -1.0f, 0}}, 0, 2, 1},    // -z: a quarter across (u just above 0.25)
        {{{-1.0f, 0.2f, -0.05f, 0}}, 0, 0, 1},   // -x: the left edge
        {{{-1.0f, -0.2f, 0.05f, 0}}, 0, 7, 2},   // -x, below the horizon: the right edge, lower half
        {{{0.1f, 1.0f, 0.0f, 0}}, 0, 4, 0},      // up: the top row
        {{{0.1f, -1.0f, 0.0f, 0}}, 0, 4, 3},     // down: the bottom row
        {{{0.05f, 0.2f, -1.0f, 0}}, 90, 4, 1},   // turned 90 degrees: the centre column faces -z
        {{{-1.0f, 0.2f, -0.05f, 0}}, 90, 2, 1},  // ... and -x a quarter across
    };
    const Probe p = build_probe();
    for (const KnownDirection& c : cases) {
        const EnvironmentLayout layout = map_layout(width, height, c.rotation_deg, 1);
        cl::Buffer result(p.context, CL_MEM_WRITE_ONLY, sizeof(cl_int));
        const cl::Buffer texels = input(p, layout.texels), cdf = input(p, layout.cdf),
                         direction = input(p, std::vector<cl_float4>{c.direction});
        cl::Kernel kernel(p.program, "probe_lookup");
        kernel.setArg(0, texels);
        kernel.setArg(1, cdf);
        kernel.setArg(2, sizeof layout.params, &layout.params);
        kernel.setArg(3, direction);
        kernel.setArg(4, result);
        cl::CommandQueue queue = p.queue;
        queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(1));
        cl_int index = -1;
        queue.enqueueReadBuffer(result, CL_TRUE, 0, sizeof index, &index);
        EXPECT_EQ(index % width, c.column) << "direction " << c.direction.s[0] << ", " << c.direction.s[1] << ", "
                                           << c.direction.s[2] << " turned " << c.rotation_deg;
        EXPECT_EQ(index / width, c.row) << "direction " << c.direction.s[0] << ", " << c.direction.s[1] << ", "
                                        << c.direction.s[2] << " turned " << c.rotation_deg;
        // The independent double-precision mapping agrees.
        const auto [column, row] = map_position(c.direction.s[0], c.direction.s[1], c.direction.s[2], c.rotation_deg,
                                                width, height);
        EXPECT_EQ(int(column), c.column);
        EXPECT_EQ(int(row), c.row);
    }
}

}  // namespace
}  // namespace orb::render::test
