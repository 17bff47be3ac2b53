// The device's traversal (kernels/intersect.cl, through the trace_rays
// kernel and RayCaster) against brute force in double precision, ray by ray:
// closest hits and shadow rays, in a cloud with a tree and a huge floor kept
// outside it, from free points and from sphere surfaces (the `self` rule),
// in the CPU variant and in the GPU variant (-DORB_SCALAR_TRAVERSAL=1).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <random>
#include <vector>

#include "ray_caster.h"
#include "render_test_support.h"
#include "scene_layout.h"

using namespace orb;
using namespace orb::render;

namespace {

struct V {
    double x, y, z;
};
V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V operator*(double s, V a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V unit(V a) { return (1.0 / std::sqrt(dot(a, a))) * a; }

// A floor of radius 1e3 (huge beside the cloud, so it stays outside the
// tree, but not so large that float's rounding of its hit points, about
// 1e-3 for a radius of 1e4, would blur the comparison) and `count` small
// spheres in a 20-wide box above it, none touching it.
Scene cloud(int count)
{
    Scene scene;
    scene.camera.position = {0.0, 10.0, 30.0};
    scene.camera.target = {0.0, 5.0, 0.0};
    const auto grey = test::add_material(scene, MaterialType::Diffuse, {0.7, 0.7, 0.7});
    const auto lamp = test::add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {5.0, 5.0, 5.0});
    test::add_sphere(scene, {0.0, -1e3, 0.0}, 1e3, grey);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> xz(-10.0, 10.0), y(1.0, 12.0), r(0.1, 0.6);
    for (int i = 0; i < count; ++i) test::add_sphere(scene, {xz(rng), y(rng), xz(rng)}, r(rng), i % 50 == 0 ? lamp : grey);
    return scene;
}

// The device's copy of each sphere slot, in double: centre and radius^2.
struct SlotSphere {
    V centre;
    double radius2;
};

std::vector<SlotSphere> slot_spheres(const SceneLayout& layout)
{
    std::vector<SlotSphere> spheres(layout.tables.spheres.size());
    for (std::size_t slot = 0; slot < spheres.size(); ++slot) {
        const device::SpherePacket& p = layout.tables.packets[slot / 4];
        const int lane = static_cast<int>(slot % 4);
        const float* cx = &p.centre_x.x;
        const float* cy = &p.centre_y.x;
        const float* cz = &p.centre_z.x;
        const float* r2 = &p.radius2.x;
        spheres[slot] = {{cx[lane], cy[lane], cz[lane]}, r2[lane]};
    }
    return spheres;
}

// Where the ray meets slot s by the kernels' rule: the near root, or the far
// one from inside the sphere or for the sphere the ray leaves (and then only
// heading into it).
std::optional<double> distance(const SlotSphere& s, V o, V d, bool is_self)
{
    const V oc = o - s.centre;
    const double b = dot(oc, d);
    const V f = oc - b * d;
    const double disc = s.radius2 - dot(f, f);
    if (disc < 0.0) return std::nullopt;
    if (is_self && b >= 0.0) return std::nullopt;
    const double root = std::sqrt(disc), near = -b - root;
    const double t = (is_self || near <= 0.0) ? -b + root : near;
    if (t <= 0.0) return std::nullopt;
    return t;
}

CastRay cast_ray(V o, V d, int self, int light = -1)
{
    CastRay ray;
    ray.origin[0] = static_cast<float>(o.x), ray.origin[1] = static_cast<float>(o.y), ray.origin[2] = static_cast<float>(o.z);
    ray.direction[0] = static_cast<float>(d.x), ray.direction[1] = static_cast<float>(d.y),
    ray.direction[2] = static_cast<float>(d.z);
    ray.self = self;
    ray.light = light;
    return ray;
}

V origin_of(const CastRay& r) { return {r.origin[0], r.origin[1], r.origin[2]}; }
V direction_of(const CastRay& r) { return {r.direction[0], r.direction[1], r.direction[2]}; }

// Rays from free points in and around the cloud and from sphere surfaces.
std::vector<CastRay> random_rays(const std::vector<SlotSphere>& spheres, int count, std::uint32_t seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0), box(-14.0, 14.0), height(0.5, 16.0);
    std::uniform_int_distribution<std::size_t> pick(0, spheres.size() - 1);
    const auto random_unit = [&] {
        for (;;) {
            const V v{u(rng), u(rng), u(rng)};
            if (const double l = dot(v, v); l > 1e-4 && l <= 1.0) return unit(v);
        }
    };
    std::vector<CastRay> rays;
    for (int i = 0; i < count; ++i) {
        if (i % 2 == 0) {
            rays.push_back(cast_ray({box(rng), height(rng), box(rng)}, random_unit(), -1));
        } else {
            const std::size_t slot = pick(rng);
            const SlotSphere& s = spheres[slot];
            // Not from the floor (its float points are too coarse to start
            // on), nor from a packet's padding slot (no sphere there).
            if (s.radius2 > 1.0 || s.radius2 <= 0.0) {
                --i;
                continue;
            }
            const V n = random_unit();
            V d = random_unit();
            if (dot(d, n) < 0.0) d = -1.0 * d;
            rays.push_back(cast_ray(s.centre + std::sqrt(s.radius2) * n, d, static_cast<int>(slot)));
        }
    }
    return rays;
}

struct BruteHit {
    int slot = -1;
    double t = INFINITY;
    double runner_up = INFINITY;  // the next nearest distance, to recognise near ties
};

BruteHit brute_force(const std::vector<SlotSphere>& spheres, const CastRay& ray)
{
    BruteHit best;
    const V o = origin_of(ray), d = direction_of(ray);
    for (std::size_t slot = 0; slot < spheres.size(); ++slot) {
        const auto t = distance(spheres[slot], o, d, static_cast<int>(slot) == ray.self);
        if (!t) continue;
        if (*t < best.t) {
            best.runner_up = best.t;
            best.t = *t;
            best.slot = static_cast<int>(slot);
        } else if (*t < best.runner_up) {
            best.runner_up = *t;
        }
    }
    return best;
}

void expect_device_matches_brute_force(const char* options)
{
    if (options) ::setenv("ORB_CL_OPTIONS", options, 1);
    const Scene scene = cloud(1500);
    const SceneLayout layout = layout_scene(scene);
    ASSERT_GT(layout.counts.bvh_node_count, 0);
    ASSERT_GT(layout.counts.outside_packet_count, 0) << "the floor should stay outside the tree";
    const std::vector<SlotSphere> spheres = slot_spheres(layout);
    RayCaster caster(DeviceSession::open(choose_device(""), {}), layout);
    if (options) ::unsetenv("ORB_CL_OPTIONS");

    // Closest hits.
    const std::vector<CastRay> rays = random_rays(spheres, 20000, 17);
    const std::vector<CastHit> hits = caster.closest(rays);
    int mismatches = 0, compared = 0, hit_count = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const BruteHit want = brute_force(spheres, rays[i]);
        // Float and double may order two spheres hit within rounding of each
        // other differently: such near ties are not compared.
        if (want.runner_up - want.t < 1e-4 * (1.0 + want.t)) continue;
        ++compared;
        hit_count += want.slot >= 0;
        const bool same = hits[i].sphere == want.slot &&
                          (want.slot < 0 || std::abs(hits[i].t - want.t) <= 1e-3 * (1.0 + want.t));
        if (!same && mismatches++ < 5)
            ADD_FAILURE() << "ray " << i << ": device hit slot " << hits[i].sphere << " at " << hits[i].t
                          << ", brute force " << want.slot << " at " << want.t;
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(compared, 19000);
    EXPECT_GT(hit_count, compared / 2) << "too few rays hit anything to test much";

    // Shadow rays towards lamps and towards other spheres, some blocked.
    std::vector<CastRay> shadow;
    std::vector<int> expected;
    std::mt19937 rng(5);
    std::uniform_int_distribution<std::size_t> pick(0, spheres.size() - 1);
    for (const CastRay& r : rays) {
        int light = static_cast<int>(pick(rng));
        while (spheres[light].radius2 <= 0.0) light = static_cast<int>(pick(rng));  // a sphere, not padding
        const V o = origin_of(r);
        const V d = unit(spheres[light].centre - o);
        CastRay ray = cast_ray(o, d, r.self, light);
        const auto t_light = distance(spheres[light], origin_of(ray), direction_of(ray), light == ray.self);
        bool blocked = false, near_tie = false;
        for (std::size_t slot = 0; t_light && slot < spheres.size(); ++slot) {
            if (static_cast<int>(slot) == light) continue;
            const auto t = distance(spheres[slot], origin_of(ray), direction_of(ray), static_cast<int>(slot) == ray.self);
            if (!t) continue;
            if (std::abs(*t - *t_light) < 1e-4 * (1.0 + *t_light)) near_tie = true;
            blocked |= *t < *t_light;
        }
        if (near_tie) continue;
        shadow.push_back(ray);
        expected.push_back(t_light && !blocked);
    }
    const std::vector<bool> visible = caster.visible(shadow);
    int shadow_mismatches = 0, seen = 0;
    for (std::size_t i = 0; i < shadow.size(); ++i) {
        seen += expected[i];
        if (visible[i] != (expected[i] != 0) && shadow_mismatches++ < 5)
            ADD_FAILURE() << "shadow ray " << i << " to slot " << shadow[i].light << ": device says visible=" << visible[i];
    }
    EXPECT_EQ(shadow_mismatches, 0);
    EXPECT_GT(shadow.size(), 19000u);
    EXPECT_GT(seen, static_cast<int>(shadow.size()) / 20) << "too few visible lights to test much";
    EXPECT_LT(seen, static_cast<int>(shadow.size()) * 19 / 20) << "too few blocked rays to test much";
}

}  // namespace

TEST(TraceKernel, ClosestHitsAndShadowRaysMatchBruteForce) { expect_device_matches_brute_force(nullptr); }

TEST(TraceKernel, GpuVariantMatchesBruteForce) { expect_device_matches_brute_force("-DORB_SCALAR_TRAVERSAL=1"); }

// The speculative traversal of NVIDIA GPUs (warp_vote.cl), every lane
// speculating as far as it can.
TEST(TraceKernel, SpeculativeTraversalMatchesBruteForce)
{
    expect_device_matches_brute_force("-DORB_SCALAR_TRAVERSAL=1 -DORB_WARP_VOTE=2");
}
