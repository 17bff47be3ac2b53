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
#include <utility>

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

bool box_contains_sphere(const BvhChild& box, const Sphere& s) {
    for (int a = 0; a < 3; ++a)
        if (box.lo[a] > s.center[a] - s.radius || box.hi[a] < s.center[a] + s.radius) return false;
    return true;
}

bool box_contains_box(const BvhChild& outer, const BvhChild& inner) {
    for (int a = 0; a < 3; ++a)
        if (outer.lo[a] > inner.lo[a] || outer.hi[a] < inner.hi[a]) return false;
    return true;
}

// Walks the subtree of node `index` (reached through box `box`, or none for
// the root) checking bounds and counts; returns its levels.
int check_node(const SphereBvh& bvh, std::span<const Sphere> spheres, std::uint32_t index, const BvhChild* box,
               std::vector<int>& seen_spheres, std::vector<int>& seen_nodes) {
    const BvhNode& node = bvh.nodes.at(index);
    ++seen_nodes.at(index);
    EXPECT_GE(node.child_count, index == 0 ? 1u : 2u) << "node " << index;
    EXPECT_LE(node.child_count, static_cast<std::uint32_t>(kBvhWidth)) << "node " << index;
    int levels = 1;
    for (std::uint32_t k = 0; k < node.child_count; ++k) {
        const BvhChild& child = node.children[k];
        if (box) {
            EXPECT_TRUE(box_contains_box(*box, child)) << "node " << index << " child " << k;
        }
        if (child.leaf()) {
            EXPECT_LE(child.count, static_cast<std::uint32_t>(kBvhMaxLeafSize));
            for (std::uint32_t i = child.first; i < child.first + child.count; ++i) {
                const std::uint32_t sphere = bvh.order.at(i);
                ++seen_spheres.at(sphere);
                EXPECT_TRUE(box_contains_sphere(child, spheres[sphere])) << "node " << index << " sphere " << sphere;
            }
            continue;
        }
        EXPECT_GT(child.first, index) << "children follow their parent";
        levels = std::max(levels, 1 + check_node(bvh, spheres, child.first, &child, seen_spheres, seen_nodes));
    }
    return levels;
}

void expect_valid(const SphereBvh& bvh, std::span<const Sphere> spheres) {
    std::vector<int> seen(spheres.size(), 0), seen_nodes(bvh.nodes.size(), 0);
    for (std::uint32_t i : bvh.outside) ++seen.at(i);
    if (!bvh.nodes.empty()) {
        const int levels = check_node(bvh, spheres, 0, nullptr, seen, seen_nodes);
        EXPECT_EQ(levels, bvh_depth(bvh));
        EXPECT_LE(bvh_stack_bound(bvh), ORB_BVH_STACK_SIZE);
    }
    for (std::size_t i = 0; i < spheres.size(); ++i) ASSERT_EQ(seen[i], 1) << "sphere " << i << " reached " << seen[i] << " times";
    for (std::size_t i = 0; i < seen_nodes.size(); ++i) ASSERT_EQ(seen_nodes[i], 1) << "node " << i << " reached " << seen_nodes[i] << " times";
    EXPECT_EQ(bvh.order.size() + bvh.outside.size(), spheres.size());
}

// Levels of the binary tree below node `index`, leaves included.
int binary_levels(const BinaryBvh& bvh, std::uint32_t index) {
    const BinaryBvhNode& node = bvh.nodes.at(index);
    if (node.leaf()) return 1;
    return 1 + std::max(binary_levels(bvh, node.first), binary_levels(bvh, node.first + 1));
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

// Where the ray enters the box, or nothing when it misses it before t_max.
std::optional<double> box_entry(const BvhChild& box, const Ray& r, double t_max) {
    double t0 = 0, t1 = t_max;
    for (int a = 0; a < 3; ++a) {
        const double inv = 1.0 / r.d[a];
        double ta = (box.lo[a] - r.o[a]) * inv, tb = (box.hi[a] - r.o[a]) * inv;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return std::nullopt;
    }
    return t0;
}

struct Hit {
    double t = INFINITY;
    std::int64_t sphere = -1;
};

// Traversal as the kernels do it: of a node's children the ray hits, the
// nearest next and the others on a stack with their entry distances, nearest
// on top, dropped when a closer hit is known by the time they are popped;
// `any` stops at the first hit. *max_stack: the most entries the stack held.
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
    struct Entry {
        double t;
        BvhChild child;
    };
    std::vector<Entry> stack;
    BvhChild current{};  // the root, as an interior child
    for (;;) {
        if (current.leaf()) {
            for (std::uint32_t k = current.first; k < current.first + current.count; ++k) {
                test(bvh.order[k]);
                if (any && best.sphere >= 0) return best;
            }
        } else {
            const BvhNode& node = bvh.nodes[current.first];
            std::vector<Entry> hits;
            for (std::uint32_t k = 0; k < node.child_count; ++k)
                if (auto t = box_entry(node.children[k], r, best.t)) hits.push_back({*t, node.children[k]});
            if (!hits.empty()) {
                std::sort(hits.begin(), hits.end(), [](const Entry& a, const Entry& b) { return a.t > b.t; });
                stack.insert(stack.end(), hits.begin(), hits.end() - 1);
                if (max_stack) *max_stack = std::max(*max_stack, static_cast<int>(stack.size()));
                current = hits.back().child;
                continue;
            }
        }
        while (!stack.empty() && stack.back().t >= best.t) stack.pop_back();
        if (stack.empty()) return best;
        current = stack.back().child;
        stack.pop_back();
    }
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

void expect_traversal_matches_brute_force(std::span<const Sphere> spheres, const SphereBvh& bvh,
                                          const std::vector<Ray>& rays) {
    int mismatches = 0, max_stack = 0, hits = 0;
    for (const Ray& r : rays) {
        const Hit want = brute_force(spheres, r, INFINITY);
        const Hit got = traverse(bvh, spheres, r, INFINITY, false, &max_stack);
        hits += want.sphere >= 0;
        if (got.sphere != want.sphere && mismatches++ < 5)
            ADD_FAILURE() << "closest hit " << got.sphere << " at " << got.t << ", brute force " << want.sphere << " at "
                          << want.t;
        // A shadow ray to a point before or after the nearest hit.
        for (double t_max : {want.sphere >= 0 ? want.t * 0.999 : 5.0, want.sphere >= 0 ? want.t * 1.001 : 50.0}) {
            const bool blocked = brute_force(spheres, r, t_max).sphere >= 0;
            if ((traverse(bvh, spheres, r, t_max, true, &max_stack).sphere >= 0) != blocked && mismatches++ < 5)
                ADD_FAILURE() << "shadow ray to t=" << t_max << ": brute force says blocked=" << blocked;
        }
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_LE(max_stack, bvh_stack_bound(bvh));
    EXPECT_GT(hits, static_cast<int>(rays.size()) / 10) << "too few rays hit anything to test much";
}

void expect_traversal_matches_brute_force(std::span<const Sphere> spheres, const SphereBvh& bvh, double box) {
    expect_traversal_matches_brute_force(spheres, bvh, random_rays(4000, 99, box));
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
    // The root's children's boxes are the grains', not the floor's.
    for (std::uint32_t k = 0; k < bvh.nodes[0].child_count; ++k)
        EXPECT_LT(bvh.nodes[0].children[k].hi[0] - bvh.nodes[0].children[k].lo[0], 5.0f);
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

// Rays from among the spheres: near a random one's centre, in random directions.
std::vector<Ray> rays_among(std::span<const Sphere> spheres, std::size_t n, double offset) {
    std::vector<Ray> rays = random_rays(n, 98, 1.0);
    std::mt19937 rng(97);
    std::uniform_int_distribution<std::size_t> which(0, spheres.size() - 1);
    std::uniform_real_distribution<double> off(-offset, offset);
    for (Ray& r : rays) {
        const Sphere& s = spheres[which(rng)];
        r.o = {s.center[0] + off(rng) * s.radius, s.center[1] + off(rng) * s.radius, s.center[2] + off(rng) * s.radius};
    }
    return rays;
}

// Spheres at x = 1.001^i: denser towards the origin, a tree deeper than a
// balanced one. Within the depth and the device's stack.
TEST(SphereBvh, ExponentiallySpacedSpheresStayWithinTheStackDepth) {
    std::vector<Sphere> spheres(20000);
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        spheres[i].center = {std::pow(1.001, static_cast<double>(i)), 0, 0};
        spheres[i].radius = 1e-3;
    }
    const BinaryBvh binary = build_binary_bvh(spheres);
    EXPECT_LE(binary_levels(binary, 0), kBvhMaxDepth);
    const SphereBvh bvh = collapse_to_4_wide(binary);
    expect_valid(bvh, spheres);
    expect_traversal_matches_brute_force(spheres, bvh, rays_among(spheres, 600, 2.0));
}

// Spheres at x = 1.2^i: the SAH splits off the far, sparse end again and
// again (42 levels without the depth rule). The rule stops it at
// kBvhMaxDepth (median splits below), and the 4-wide tree fits the device's
// stack: the cost rule's tree would not here, so this one is the level rule's.
TEST(SphereBvh, AChainOfClustersIsCutAtTheDepthLimitAndFitsTheStack) {
    std::vector<Sphere> spheres(400);
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        const double x = std::pow(1.2, static_cast<double>(i));
        spheres[i].center = {x, 0, 0};
        spheres[i].radius = 0.01 * x;
    }
    const BinaryBvh binary = build_binary_bvh(spheres);
    EXPECT_EQ(binary_levels(binary, 0), kBvhMaxDepth);
    const SphereBvh bvh = collapse_to_4_wide(binary);
    expect_valid(bvh, spheres);
    EXPECT_GT(bvh_stack_bound(collapse_by_cost(binary)), ORB_BVH_STACK_SIZE);
    EXPECT_EQ(bvh.nodes.size(), collapse_by_levels(binary).nodes.size());
    expect_traversal_matches_brute_force(spheres, bvh, rays_among(spheres, 2000, 2.0));
}

// The 4-wide tree holds the binary tree's leaves, each once, and is shallower.
void expect_same_leaves(const BinaryBvh& binary, const SphereBvh& bvh) {
    std::multiset<std::pair<std::uint32_t, std::uint32_t>> binary_leaves, wide_leaves;
    for (const BinaryBvhNode& node : binary.nodes)
        if (node.leaf()) binary_leaves.insert({node.first, node.count});
    for (const BvhNode& node : bvh.nodes)
        for (std::uint32_t k = 0; k < node.child_count; ++k)
            if (node.children[k].leaf()) wide_leaves.insert({node.children[k].first, node.children[k].count});
    EXPECT_EQ(wide_leaves, binary_leaves);
    EXPECT_EQ(bvh.order, binary.order);
    EXPECT_EQ(bvh.outside, binary.outside);
}

double area(const BvhChild& box) {
    const double x = double(box.hi[0]) - box.lo[0], y = double(box.hi[1]) - box.lo[1], z = double(box.hi[2]) - box.lo[2];
    return 2.0 * (x * y + y * z + z * x);
}

// The surface area heuristic's cost of a 4-wide tree (sphere_bvh_collapse.cpp):
// each node entered costs one, each leaf entered one, weighted by box area.
double sah_cost(const SphereBvh& bvh) {
    double cost = 0;
    for (const BvhNode& node : bvh.nodes)
        for (std::uint32_t k = 0; k < node.child_count; ++k) cost += area(node.children[k]);
    return cost;
}

TEST(SphereBvh, CollapsingKeepsTheBinaryLeavesAndTheCostRuleBeatsTheLevelRule) {
    const auto spheres = random_spheres(5000, 7);
    const BinaryBvh binary = build_binary_bvh(spheres);
    const int binary_depth = binary_levels(binary, 0);
    const SphereBvh by_cost = collapse_by_cost(binary), by_levels = collapse_by_levels(binary);
    for (const SphereBvh* bvh : {&by_cost, &by_levels}) {
        expect_same_leaves(binary, *bvh);
        expect_valid(*bvh, spheres);
        expect_traversal_matches_brute_force(spheres, *bvh, 11.0);
    }
    EXPECT_LE(bvh_depth(by_levels), binary_depth / 2);
    EXPECT_LE(bvh_stack_bound(by_levels), 3 * (binary_depth / 2));
    // The level rule's cut is one the dynamic programme considers, so the
    // cost rule's tree costs no more, and it packs the leaves into fewer nodes.
    EXPECT_LE(sah_cost(by_cost), sah_cost(by_levels) * (1.0 + 1e-12));
    EXPECT_LT(by_cost.nodes.size(), by_levels.nodes.size());
}

// The cost rule's tree is kept only while it fits the stack; else the level
// rule's, which always does.
TEST(SphereBvh, ATreeBeyondTheStackFallsBackToTheLevelRule) {
    const auto spheres = random_spheres(5000, 8);
    const BinaryBvh binary = build_binary_bvh(spheres);
    const int cost_bound = bvh_stack_bound(collapse_by_cost(binary));
    const SphereBvh fits = collapse_to_4_wide(binary, cost_bound);
    const SphereBvh falls_back = collapse_to_4_wide(binary, cost_bound - 1);
    EXPECT_EQ(fits.nodes.size(), collapse_by_cost(binary).nodes.size());
    const SphereBvh by_levels = collapse_by_levels(binary);
    ASSERT_EQ(falls_back.nodes.size(), by_levels.nodes.size());
    EXPECT_EQ(std::memcmp(falls_back.nodes.data(), by_levels.nodes.data(), by_levels.nodes.size() * sizeof(BvhNode)), 0);
}

namespace {

BvhSettings on_threads(unsigned threads) {
    BvhSettings settings;
    settings.threads = threads;
    return settings;
}

// The same nodes, byte for byte, and the same leaf order (a BinaryBvh or a SphereBvh).
template <class Tree>
void expect_same_tree(const Tree& a, const Tree& b) {
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(a.order, b.order);
    EXPECT_EQ(std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(a.nodes[0])), 0);
}

}  // namespace

TEST(SphereBvh, OneThreadAndTwoThreadsBuildTheSameTree) {
    const auto spheres = random_spheres(50000, 6);
    expect_same_tree(build_sphere_bvh(spheres, on_threads(1)), build_sphere_bvh(spheres, on_threads(2)));
}

// A few large spheres apart from a cloud make the root's SAH split cut them
// off: the cloud must still be shared between the threads (the 10 M-sphere
// benchmark scene built on one thread before), and the tree stays the same.
TEST(SphereBvh, TwoThreadsShareTheCloudWhenTheRootSplitsOffAFewSpheres) {
    auto spheres = random_spheres(40000, 11);
    for (int k = 0; k < 3; ++k) {
        Sphere far;
        far.center = {1000.0 + 50.0 * k, 1000.0, 1000.0};
        far.radius = 20.0;
        spheres.push_back(far);
    }
    const BinaryBvh a = build_binary_bvh(spheres, on_threads(1)), b = build_binary_bvh(spheres, on_threads(2));
    expect_same_tree(a, b);
    // The root's split is the uneven one this test is about: one child's box
    // holds only the three far spheres.
    const std::uint32_t first = a.nodes[0].first;
    EXPECT_TRUE(a.nodes[first].lo[0] > 900.0f || a.nodes[first + 1].lo[0] > 900.0f);
    EXPECT_EQ(a.most_spheres_on_one_thread, spheres.size());
    // Two threads: neither builds much more than half of the cloud.
    EXPECT_LE(b.most_spheres_on_one_thread, spheres.size() * 3 / 4);
    EXPECT_GE(b.most_spheres_on_one_thread, spheres.size() / 2);
}

// Refitting (sphere_bvh_refit.cpp). Unmoved spheres give back the boxes the
// build made, bit for bit; moved ones a tree whose boxes nest and hold every
// sphere, which traversal reads as it reads a new build; and the SAH cost
// grows with the motion.
TEST(SphereBvhRefit, UnmovedSpheresGiveTheBuiltBoxes) {
    const auto spheres = random_spheres(5000, 21);
    const SphereBvh built = build_sphere_bvh(spheres);
    SphereBvh refitted = built;
    refit_sphere_bvh(refitted, spheres);
    ASSERT_EQ(refitted.nodes.size(), built.nodes.size());
    for (std::size_t i = 0; i < built.nodes.size(); ++i)
        for (std::uint32_t k = 0; k < built.nodes[i].child_count; ++k)
            for (int a = 0; a < 3; ++a) {
                ASSERT_EQ(refitted.nodes[i].children[k].lo[a], built.nodes[i].children[k].lo[a]) << i << " " << k;
                ASSERT_EQ(refitted.nodes[i].children[k].hi[a], built.nodes[i].children[k].hi[a]) << i << " " << k;
            }
    EXPECT_EQ(bvh_sah_cost(refitted), bvh_sah_cost(built));
}

TEST(SphereBvhRefit, MovedSpheresKeepAValidTreeThatTraversalReadsRight) {
    auto spheres = random_spheres(3000, 22, 5.0, 0.05, 0.5);
    SphereBvh bvh = build_sphere_bvh(spheres);
    const double built_cost = bvh_sah_cost(bvh);
    std::mt19937 rng(23);
    std::normal_distribution<double> step(0.0, 0.3);
    double previous_cost = built_cost;
    for (int frame = 0; frame < 3; ++frame) {
        for (Sphere& s : spheres)
            for (double& c : s.center) c += step(rng);
        refit_sphere_bvh(bvh, spheres);
        expect_valid(bvh, spheres);
        expect_traversal_matches_brute_force(spheres, bvh, 6.0);
        const double cost = bvh_sah_cost(bvh);
        EXPECT_GT(cost, previous_cost) << "frame " << frame << ": spheres drifting apart in a tree built for where they were";
        previous_cost = cost;
    }
    EXPECT_GT(previous_cost, 1.2 * built_cost);
}

// The SAH cost of a tree against the count it weighs: a ray through the root
// meets the root's four boxes and, in a tree of one leaf, its spheres.
TEST(SphereBvhRefit, TheCostOfATreeOfOneLeafIsItsBoxesAndSpheres) {
    const auto spheres = random_spheres(20, 24);
    BvhSettings settings;
    settings.min_spheres_for_tree = 1;
    const SphereBvh bvh = build_sphere_bvh(spheres, settings);
    ASSERT_FALSE(bvh.nodes.empty());
    // Every child box lies in the root box, so the cost lies between the root's
    // four box tests and that plus every child entered for sure.
    double at_most = kBvhWidth;
    for (const BvhNode& node : bvh.nodes)
        for (std::uint32_t k = 0; k < node.child_count; ++k)
            at_most += node.children[k].leaf() ? node.children[k].count : kBvhWidth;
    EXPECT_GT(bvh_sah_cost(bvh), static_cast<double>(kBvhWidth));
    EXPECT_LE(bvh_sah_cost(bvh), at_most);
}
