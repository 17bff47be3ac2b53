// The sphere BVH's invariants, and a reference traversal on the host that
// must find exactly what testing every sphere finds, for closest hits and
// for shadow rays.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <cstring>
#include <set>

#include "sphere_bvh.h"

using orb::Sphere;
using orb::Vec3;
using namespace orb::render;

namespace {

std::vector<Sphere> random_spheres(std::size_t n, std::uint32_t seed, double box = 10.0, double rmin = 0.01,
                                   double rmax = 0.3) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-box, box), rad(rmin, rmax);
    std::vector<Sphere> spheres(n);
    for (auto& s : spheres) {
        s.center = {pos(rng), pos(rng), pos(rng)};
        s.radius = rad(rng);
    }
    return spheres;
}

bool box_contains_sphere(const BvhNode& node, const Sphere& s) {
    for (int a = 0; a < 3; ++a)
        if (node.lo[a] > s.center[a] - s.radius || node.hi[a] < s.center[a] + s.radius) return false;
    return true;
}

bool box_contains_box(const BvhNode& outer, const BvhNode& inner) {
    for (int a = 0; a < 3; ++a)
        if (outer.lo[a] > inner.lo[a] || outer.hi[a] < inner.hi[a]) return false;
    return true;
}

// Walks the tree checking bounds; returns the deepest level reached.
int check_node(const SphereBvh& bvh, std::span<const Sphere> spheres, std::uint32_t index, int depth,
               std::vector<int>& seen) {
    const BvhNode& node = bvh.nodes.at(index);
    if (node.count > 0) {
        EXPECT_LE(node.count, static_cast<std::uint32_t>(kBvhMaxLeafSize));
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
            const std::uint32_t sphere = bvh.order.at(i);
            ++seen.at(sphere);
            EXPECT_TRUE(box_contains_sphere(node, spheres[sphere])) << "leaf " << index << " sphere " << sphere;
        }
        return depth;
    }
    EXPECT_GT(node.first, index) << "children follow their parent";
    EXPECT_TRUE(box_contains_box(node, bvh.nodes.at(node.first))) << index;
    EXPECT_TRUE(box_contains_box(node, bvh.nodes.at(node.first + 1))) << index;
    return std::max(check_node(bvh, spheres, node.first, depth + 1, seen),
                    check_node(bvh, spheres, node.first + 1, depth + 1, seen));
}

void expect_valid(const SphereBvh& bvh, std::span<const Sphere> spheres) {
    std::vector<int> seen(spheres.size(), 0);
    for (std::uint32_t i : bvh.outside) ++seen.at(i);
    if (!bvh.nodes.empty()) {
        const int depth = check_node(bvh, spheres, 0, 1, seen);
        EXPECT_LE(depth, kBvhMaxDepth);
    }
    for (std::size_t i = 0; i < spheres.size(); ++i) ASSERT_EQ(seen[i], 1) << "sphere " << i << " reached " << seen[i] << " times";
    EXPECT_EQ(bvh.order.size() + bvh.outside.size(), spheres.size());
}

struct Ray {
    Vec3 o, d;
};

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Nearest t > eps where the ray enters or leaves the sphere.
std::optional<double> hit_sphere(const Sphere& s, const Ray& r, double t_max) {
    const Vec3 oc{r.o[0] - s.center[0], r.o[1] - s.center[1], r.o[2] - s.center[2]};
    const double b = dot(oc, r.d), c = dot(oc, oc) - s.radius * s.radius;
    const double disc = b * b - c;
    if (disc < 0) return std::nullopt;
    const double root = std::sqrt(disc);
    for (double t : {-b - root, -b + root})
        if (t > 1e-9 && t < t_max) return t;
    return std::nullopt;
}

bool hit_box(const BvhNode& n, const Ray& r, double t_max) {
    double t0 = 0, t1 = t_max;
    const Vec3& o = r.o;
    const Vec3& d = r.d;
    for (int a = 0; a < 3; ++a) {
        const double inv = 1.0 / d[a];
        double ta = (n.lo[a] - o[a]) * inv, tb = (n.hi[a] - o[a]) * inv;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

struct Hit {
    double t = INFINITY;
    std::int64_t sphere = -1;
};

// Ordered traversal with a stack, as the kernels do; `any` stops at the first hit.
Hit traverse(const SphereBvh& bvh, std::span<const Sphere> spheres, const Ray& r, double t_max, bool any,
             int* max_stack = nullptr) {
    Hit best{t_max, -1};
    auto test = [&](std::uint32_t i) {
        if (auto t = hit_sphere(spheres[i], r, best.t)) best = {*t, i};
    };
    for (std::uint32_t i : bvh.outside) {
        test(i);
        if (any && best.sphere >= 0) return best;
    }
    if (bvh.nodes.empty()) return best;
    std::uint32_t stack[kBvhMaxDepth];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const BvhNode& n = bvh.nodes[stack[--top]];
        if (!hit_box(n, r, best.t)) continue;
        if (n.count > 0) {
            for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
                test(bvh.order[k]);
                if (any && best.sphere >= 0) return best;
            }
            continue;
        }
        stack[top++] = n.first;
        stack[top++] = n.first + 1;
        if (max_stack) *max_stack = std::max(*max_stack, top);
    }
    return best;
}

Hit brute_force(std::span<const Sphere> spheres, const Ray& r, double t_max) {
    Hit best{t_max, -1};
    for (std::uint32_t i = 0; i < spheres.size(); ++i)
        if (auto t = hit_sphere(spheres[i], r, best.t)) best = {*t, i};
    return best;
}

std::vector<Ray> random_rays(std::size_t n, std::uint32_t seed, double box) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-box, box);
    std::normal_distribution<double> dir;
    std::vector<Ray> rays(n);
    for (auto& r : rays) {
        r.o = {pos(rng), pos(rng), pos(rng)};
        Vec3 d{dir(rng), dir(rng), dir(rng)};
        const double len = std::sqrt(dot(d, d));
        r.d = {d[0] / len, d[1] / len, d[2] / len};
    }
    return rays;
}

void expect_traversal_matches_brute_force(std::span<const Sphere> spheres, const SphereBvh& bvh, double box) {
    int mismatches = 0;
    for (const Ray& r : random_rays(4000, 99, box)) {
        const Hit want = brute_force(spheres, r, INFINITY);
        const Hit got = traverse(bvh, spheres, r, INFINITY, false);
        if (got.sphere != want.sphere && mismatches++ < 5)
            ADD_FAILURE() << "closest hit " << got.sphere << " at " << got.t << ", brute force " << want.sphere << " at "
                          << want.t;
        // A shadow ray to a point before or after the nearest hit.
        for (double t_max : {want.sphere >= 0 ? want.t * 0.999 : 5.0, want.sphere >= 0 ? want.t * 1.001 : 50.0}) {
            const bool blocked = brute_force(spheres, r, t_max).sphere >= 0;
            if ((traverse(bvh, spheres, r, t_max, true).sphere >= 0) != blocked && mismatches++ < 5)
                ADD_FAILURE() << "shadow ray to t=" << t_max << ": brute force says blocked=" << blocked;
        }
    }
    EXPECT_EQ(mismatches, 0);
}

}  // namespace

TEST(SphereBvh, RandomSpheresEveryOneReachableOnceAndBoundsNest) {
    const auto spheres = random_spheres(10000, 1);
    const SphereBvh bvh = build_sphere_bvh(spheres);
    EXPECT_TRUE(bvh.outside.empty());
    expect_valid(bvh, spheres);
}

TEST(SphereBvh, TraversalFindsWhatBruteForceFinds) {
    const auto spheres = random_spheres(3000, 2, 5.0, 0.05, 0.5);
    const SphereBvh bvh = build_sphere_bvh(spheres);
    expect_traversal_matches_brute_force(spheres, bvh, 6.0);
}

TEST(SphereBvh, AHugeFloorStaysOutsideTheTreeAndGrainsGoIn) {
    auto spheres = random_spheres(2000, 3, 2.0, 0.05, 0.1);
    Sphere floor;
    floor.center = {0, -1e4 - 2.0, 0};
    floor.radius = 1e4;
    spheres.insert(spheres.begin() + 700, floor);
    const SphereBvh bvh = build_sphere_bvh(spheres);
    EXPECT_EQ(bvh.outside, (std::vector<std::uint32_t>{700}));
    expect_valid(bvh, spheres);
    // The root box is the grains', not the floor's.
    EXPECT_LT(bvh.nodes[0].hi[0] - bvh.nodes[0].lo[0], 5.0f);
    expect_traversal_matches_brute_force(spheres, bvh, 3.0);
}

TEST(SphereBvh, ASmallSceneIsAllOutside) {
    const auto spheres = random_spheres(9, 4);
    const SphereBvh bvh = build_sphere_bvh(spheres);
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_EQ(bvh.outside.size(), 9u);
    expect_valid(bvh, spheres);
}

TEST(SphereBvh, ManyHugeSpheresKeepOnlyTheLargestOutside) {
    auto spheres = random_spheres(500, 5, 1.0, 2.0, 3.0);  // every box spans a good part of the scene
    BvhSettings settings;
    settings.max_outside = 8;
    const SphereBvh bvh = build_sphere_bvh(spheres, settings);
    ASSERT_EQ(bvh.outside.size(), 8u);
    double smallest_outside = INFINITY, largest_inside = 0;
    for (std::uint32_t i : bvh.outside) smallest_outside = std::min(smallest_outside, spheres[i].radius);
    for (std::uint32_t i : bvh.order) largest_inside = std::max(largest_inside, spheres[i].radius);
    EXPECT_GE(smallest_outside, largest_inside);
    expect_valid(bvh, spheres);
    expect_traversal_matches_brute_force(spheres, bvh, 4.0);
}

TEST(SphereBvh, CoincidentSpheresStillMakeABoundedTree) {
    std::vector<Sphere> spheres(5000);
    for (auto& s : spheres) s.radius = 0.5;
    const SphereBvh bvh = build_sphere_bvh(spheres);
    expect_valid(bvh, spheres);
}

TEST(SphereBvh, ExponentiallySpacedSpheresStayWithinTheStackDepth) {
    std::vector<Sphere> spheres(20000);
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        spheres[i].center = {std::pow(1.001, static_cast<double>(i)), 0, 0};
        spheres[i].radius = 1e-3;
    }
    const SphereBvh bvh = build_sphere_bvh(spheres);
    expect_valid(bvh, spheres);
}

TEST(SphereBvh, OneThreadAndTwoThreadsBuildTheSameTree) {
    const auto spheres = random_spheres(50000, 6);
    BvhSettings one, two;
    one.threads = 1;
    two.threads = 2;
    const SphereBvh a = build_sphere_bvh(spheres, one), b = build_sphere_bvh(spheres, two);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(a.order, b.order);
    EXPECT_EQ(std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(BvhNode)), 0);
}
