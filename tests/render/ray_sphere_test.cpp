// The ray-sphere test of kernels/intersect.cl, one text in three forms (one
// ray and one sphere; one ray and a packet of four spheres; four lanes' rays
// and one sphere), called directly on the default device (PoCL here) in the
// program render_pass is built in, with its options and four lanes. Each
// form must follow the rules written at its home: the near root, the
// far one from inside, nothing behind the ray, the sphere a ray leaves only
// when the ray heads back into it, no hit for a NaN ray or a padding lane;
// and all three must give the same distance as a double-precision reference
// of the same formula, up to float rounding.
#define CL_HPP_ENABLE_EXCEPTIONS
#include <CL/opencl.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "orb/render/device.h"
#include "opencl_devices.h"
#include "program_build.h"
#include "program_source.h"

namespace orb::render::test {
namespace {

// Case i is tested in lane i % 4 of the packet and of the lanes; the other
// lanes hold padding spheres (radius squared -1) and rays that miss.
constexpr const char* kProbeKernel = R"CL(
__kernel void probe_ray_sphere(__global const float4* origin, __global const float4* direction,
                               __global const float4* sphere, __global const int* is_self, __global float4* out)
{
    const int i = get_global_id(0);
    const int lane = i & 3;
    const float3 o = origin[i].xyz, d = direction[i].xyz, centre = sphere[i].xyz;
    const float radius2 = sphere[i].w;
    const int4 in_lane = (int4)(0, 1, 2, 3) == (int4)(lane);
    const int4 self4 = in_lane & (int4)(is_self[i] ? -1 : 0);

    const float scalar = ray_sphere_distance(o, d, centre, radius2, is_self[i]);

    const packet_v3 centres = p4_make(select((float4)(0.0f), (float4)(centre.x), in_lane),
                                      select((float4)(0.0f), (float4)(centre.y), in_lane),
                                      select((float4)(0.0f), (float4)(centre.z), in_lane));
    const float4 packet = ray_spheres_distance(p4_splat(o), p4_splat(d), centres,
                                               select((float4)(-1.0f), (float4)(radius2), in_lane), self4);

    const float3 away = (float3)(0.0f, 0.0f, 1.0f);  // the other lanes' rays start far off, heading away
    const lv3 lane_o = lv3_select(lv3_splat(centre + (float3)(0.0f, 0.0f, 1e6f)), lv3_splat(o), in_lane);
    const lv3 lane_d = lv3_select(lv3_splat(away), lv3_splat(d), in_lane);
    const lfloat lanes = lanes_sphere_distance(lane_o, lane_d, lv3_splat(centre), (lfloat)(radius2), self4);

    out[i] = (float4)(scalar, ((const float*)&packet)[lane], ((const float*)&lanes)[lane], 0.0f);
}
)CL";

constexpr float kNoHit = 1e30f;  // ORB_NO_HIT

using Vec = std::array<double, 3>;

struct Case {
    Vec o, d, centre;
    float radius2 = 1;  // the radius squared, as stored (-1: a padding lane)
    bool self = false;
};

struct Distances {
    float scalar, packet, lanes;
};

class RaySphereProbe {
public:
    RaySphereProbe()
    {
        const DeviceInfo info = choose_device("");
        device_ = opencl_device(info.index);
        context_ = cl::Context(device_);
        queue_ = cl::CommandQueue(context_, device_);
        program_ = cl::Program(context_, program_source("") + kProbeKernel);
        ProgramOptions options;
        options.features.lanes = 4;  // the lanes' form exists at widths above 1
        try {
            program_.build({device_}, program_options_text(options).c_str());
        } catch (const cl::Error&) {
            throw std::runtime_error("probe kernel failed to build: " +
                                     program_.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device_));
        }
    }

    std::vector<Distances> run(const std::vector<Case>& cases)
    {
        std::vector<cl_float4> origin, direction, sphere;
        std::vector<cl_int> self;
        const auto float4 = [](const Vec& v, float w) {
            return cl_float4{{static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), w}};
        };
        for (const Case& c : cases) {
            origin.push_back(float4(c.o, 0));
            direction.push_back(float4(c.d, 0));
            sphere.push_back(float4(c.centre, c.radius2));
            self.push_back(c.self ? 1 : 0);
        }
        const auto input = [&](auto& v) {
            return cl::Buffer(context_, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, v.size() * sizeof(v[0]), v.data());
        };
        // Each buffer lives until the kernel has run: an argument holds no reference.
        const cl::Buffer origins = input(origin), directions = input(direction), spheres = input(sphere),
                         selves = input(self);
        cl::Buffer out(context_, CL_MEM_WRITE_ONLY, cases.size() * sizeof(cl_float4));
        cl::Kernel kernel(program_, "probe_ray_sphere");
        kernel.setArg(0, origins);
        kernel.setArg(1, directions);
        kernel.setArg(2, spheres);
        kernel.setArg(3, selves);
        kernel.setArg(4, out);
        queue_.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(cases.size()));
        std::vector<cl_float4> result(cases.size());
        queue_.enqueueReadBuffer(out, CL_TRUE, 0, result.size() * sizeof(result[0]), result.data());
        std::vector<Distances> distances;
        for (const cl_float4& r : result) distances.push_back({r.s[0], r.s[1], r.s[2]});
        return distances;
    }

private:
    cl::Device device_;
    cl::Context context_;
    cl::CommandQueue queue_;
    cl::Program program_;
};

double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec unit(const Vec& v)
{
    const double length = std::sqrt(dot(v, v));
    return {v[0] / length, v[1] / length, v[2] / length};
}

struct Reference {
    double t;       // the distance, or kNoHit
    double disc;    // the discriminant
    double margin;  // how far the case lies from a boundary between outcomes (a grazing ray, a root at the
                    // origin, a ray along its own sphere's surface), relative to the radius
};

// The rules in double precision, from the inputs rounded to float as the
// device gets them.
Reference reference(const Case& c)
{
    const auto f = [](double v) { return static_cast<double>(static_cast<float>(v)); };
    const Vec d{f(c.d[0]), f(c.d[1]), f(c.d[2])};
    const Vec oc{f(c.o[0]) - f(c.centre[0]), f(c.o[1]) - f(c.centre[1]), f(c.o[2]) - f(c.centre[2])};
    const double b = dot(oc, d);
    const Vec p{oc[0] - b * d[0], oc[1] - b * d[1], oc[2] - b * d[2]};
    const double radius2 = c.radius2, radius = std::sqrt(radius2);
    const double disc = radius2 - dot(p, p);
    const double s = std::sqrt(std::max(disc, 0.0));
    const double t_near = -b - s;
    const double t = c.self || t_near <= 0 ? -b + s : t_near;
    const double margin = std::min({std::abs(disc) / radius2, std::abs(t_near) / radius, std::abs(t) / radius,
                                    c.self ? std::abs(b) / radius : 1.0});
    const bool hit = disc >= 0 && t > 0 && !(c.self && b >= 0);
    return {hit ? t : kNoHit, disc, margin};
}

TEST(RaySphere, EveryFormFollowsTheRules)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    struct Named {
        const char* what;
        Case c;
        float expected;
    };
    const std::vector<Named> cases = {
        {"head-on from outside: the near root", {{0, 0, -5}, {0, 0, 1}, {0, 0, 0}}, 4},
        {"from the centre: the far root", {{0, 0, 0}, {0, 0, 1}, {0, 0, 0}}, 1},
        {"a sphere behind the ray", {{0, 0, 5}, {0, 0, 1}, {0, 0, 0}}, kNoHit},
        {"a ray passing beside", {{1.5, 0, -5}, {0, 0, 1}, {0, 0, 0}}, kNoHit},
        {"leaving its own sphere outwards", {{0, 0, 1}, {0, 0, 1}, {0, 0, 0}, 1, true}, kNoHit},
        {"leaving its own sphere inwards: the far root", {{0, 0, 1}, {0, 0, -1}, {0, 0, 0}, 1, true}, 2},
        {"another sphere's surface, heading in: the far root", {{0, 0, 1}, {0, 0, -1}, {0, 0, 0}}, 2},
        // A ray's origin rounded to just outside the sphere it leaves: the
        // near root is the surface it stands on, so only the far root counts.
        {"leaving its own sphere inwards from just outside", {{0, 0, 1.0001f}, {0, 0, -1}, {0, 0, 0}, 1, true},
         1.0001f + 1.0f},
        {"another sphere from just outside: the near root", {{0, 0, 1.0001f}, {0, 0, -1}, {0, 0, 0}}, 1.0001f - 1.0f},
        {"a radius-2 sphere ahead", {{0, 0, -5}, {0, 0, 1}, {0, 0, 1}, 4}, 4},
        {"a radius-1e4 wall one unit away", {{0, 0, 0}, {1, 0, 0}, {1e4 + 1, 0, 0}, 1e8f}, 1},
        {"a NaN origin", {{nan, 0, -5}, {0, 0, 1}, {0, 0, 0}}, kNoHit},
        {"a padding lane", {{0, 0, -5}, {0, 0, 1}, {0, 0, 0}, -1}, kNoHit},
    };
    std::vector<Case> input;
    for (const Named& n : cases) input.push_back(n.c);
    RaySphereProbe probe;
    const std::vector<Distances> got = probe.run(input);
    for (std::size_t i = 0; i < cases.size(); ++i) {
        EXPECT_EQ(got[i].scalar, cases[i].expected) << cases[i].what << ", scalar form";
        EXPECT_EQ(got[i].packet, cases[i].expected) << cases[i].what << ", packet form";
        EXPECT_EQ(got[i].lanes, cases[i].expected) << cases[i].what << ", lanes' form";
    }
}

// Random rays (from outside, from inside, leaving a sphere's surface either
// way) against spheres of radius 0.01 to 1e4: the three forms agree with the
// double-precision reference on hit or miss wherever the case is not within
// float rounding of a boundary, and on the distance up to float rounding: a
// few ulps of |oc| and the radius, and of the squared radius carried into
// the square root of the discriminant (r^2 / sqrt(disc)).
TEST(RaySphere, EveryFormAgreesWithTheReference)
{
    std::mt19937 rng(20261202);
    std::uniform_real_distribution<double> uniform(-1, 1);
    std::vector<Case> cases;
    for (int i = 0; i < 4096; ++i) {
        Case c;
        const double radius = std::pow(10.0, 1 + 3 * uniform(rng));  // 0.01 to 1e4
        c.radius2 = static_cast<float>(radius * radius);
        c.centre = {uniform(rng) * 100, uniform(rng) * 100, uniform(rng) * 100};
        c.d = unit({uniform(rng), uniform(rng), uniform(rng)});
        const Vec offset = unit({uniform(rng), uniform(rng), uniform(rng)});
        const double from = i % 4 == 0 ? 3 : i % 4 == 1 ? 0.5 : i % 4 == 2 ? 1 : 1.5;  // in radii; 1: on the surface
        for (int k = 0; k < 3; ++k) c.o[k] = c.centre[k] + offset[k] * from * radius;
        c.self = i % 4 == 2;
        if (i % 4 == 3)  // roughly at the sphere from outside: hits and misses
            c.d = unit({c.centre[0] - c.o[0] + uniform(rng) * 2 * radius, c.centre[1] - c.o[1] + uniform(rng) * 2 * radius,
                        c.centre[2] - c.o[2] + uniform(rng) * 2 * radius});
        cases.push_back(c);
    }
    RaySphereProbe probe;
    const std::vector<Distances> got = probe.run(cases);
    int compared = 0, hits = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const Reference expected_case = reference(cases[i]);
        if (expected_case.margin < 1e-3) continue;  // within rounding of a boundary between outcomes
        const double expected = expected_case.t;
        ++compared;
        hits += expected < kNoHit;
        const Case& c = cases[i];
        const Vec oc{c.o[0] - c.centre[0], c.o[1] - c.centre[1], c.o[2] - c.centre[2]};
        const double radius = std::sqrt(static_cast<double>(c.radius2));
        const double tolerance = 8 * std::numeric_limits<float>::epsilon() *
                                 (std::sqrt(dot(oc, oc)) + radius + radius * radius / std::sqrt(expected_case.disc));
        for (const auto& [form, t] : {std::pair{"scalar", got[i].scalar}, std::pair{"packet", got[i].packet},
                                      std::pair{"lanes", got[i].lanes}}) {
            if (expected >= kNoHit) {
                EXPECT_EQ(t, kNoHit) << "case " << i << ", " << form << " form";
            } else {
                EXPECT_NEAR(t, expected, tolerance) << "case " << i << ", " << form << " form";
            }
        }
    }
    // The cases must exercise both outcomes.
    EXPECT_GT(compared, 3000);
    EXPECT_GT(hits, 1000);
    EXPECT_GT(compared - hits, 500);
}

}  // namespace
}  // namespace orb::render::test
