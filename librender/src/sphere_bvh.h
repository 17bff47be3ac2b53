// A bounding volume hierarchy over spheres, built on the host for the
// kernels' closest-hit and shadow-ray traversal (docs/rendering.md).
//
// Built in two steps: a binary tree by the binned surface area heuristic
// (sphere_bvh_build.cpp), then collapsed into a 4-wide tree
// (sphere_bvh_collapse.cpp), whose nodes hold the boxes of up to four
// children, so that a CPU tests all four with one vector instruction per
// float4 and a GPU thread reads them in a few wide loads. Leaves hold at most
// four spheres, so that one leaf is one packet of PoCL's four-wide
// intersection. Boxes are rounded outward to float, so a float ray test never
// misses a sphere the double box contains.
//
// Spheres that dwarf the scene (a floor of radius 10^4 beside grains of
// radius 0.1, the walls of the Cornell box) would enlarge every box they
// share: they stay outside the tree and every ray tests them directly, as
// do all spheres of a scene too small for a tree to pay.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "orb/tables/device_types.h"
#include "orb/scene/scene.h"

namespace orb::render {

inline constexpr int kBvhMaxLeafSize = 4;
inline constexpr int kBvhWidth = 4;

// No root-to-leaf path of the binary tree has more levels (leaves counted).
// When each interior node of the 4-wide tree spans at least two of them on
// the way down (the level rule below), a path meets at most
// kBvhMaxDepth / 2 interior nodes, and ordered traversal, which defers at
// most three children at each, never holds more than 3 * (kBvhMaxDepth / 2)
// deferred nodes.
inline constexpr int kBvhMaxDepth = 32;
static_assert((kBvhWidth - 1) * (kBvhMaxDepth / 2) <= ORB_BVH_STACK_SIZE,
              "the device's traversal stack holds every node a tree of this depth defers");

// The binary tree, as built: children adjacent (an interior node's right
// child is its left child + 1), depth-first order.
struct BinaryBvhNode {
    float lo[3];
    std::uint32_t first;  // interior: left child's index; leaf: first entry of BinaryBvh::order
    float hi[3];
    std::uint32_t count;  // 0 for an interior node; a leaf's sphere count (1..kBvhMaxLeafSize)
    bool leaf() const { return count > 0; }
};

struct BinaryBvh {
    std::vector<BinaryBvhNode> nodes;    // nodes[0] is the root; empty when no sphere is in the tree
    std::vector<std::uint32_t> order;    // sphere indices in leaf order
    std::vector<std::uint32_t> outside;  // spheres every ray tests, outside the tree, in index order
    // The most spheres one thread built subtrees over, not counting those it
    // handed to other threads (BvhSettings::threads): with two threads about
    // half of them. The tree is the same however the work was shared.
    std::uint32_t most_spheres_on_one_thread = 0;
};

// One child of a 4-wide node: its box, and an interior node or a leaf.
struct BvhChild {
    float lo[3];
    float hi[3];
    std::uint32_t first;  // interior: index into SphereBvh::nodes; leaf: first entry of SphereBvh::order
    std::uint32_t count;  // 0 for an interior node; a leaf's sphere count (1..kBvhMaxLeafSize)
    bool leaf() const { return count > 0; }
};

// A node of the 4-wide tree: children[0, child_count) are used (1..4; fewer
// than two only in the root of a tree of one leaf). Interior children come
// after their parent (depth-first order, first child next).
struct BvhNode {
    std::array<BvhChild, kBvhWidth> children;
    std::uint32_t child_count;
};

struct SphereBvh {
    std::vector<BvhNode> nodes;          // nodes[0] is the root; empty when no sphere is in the tree
    std::vector<std::uint32_t> order;    // sphere indices in leaf order
    std::vector<std::uint32_t> outside;  // spheres every ray tests, outside the tree, in index order
};

struct BvhSettings {
    int bins = 16;                          // SAH candidate planes per axis
    double huge_area_fraction = 0.1;        // a sphere whose box has this share of the scene box's area is huge
    std::size_t max_outside = 64;           // at most this many huge spheres stay outside (the largest)
    std::size_t min_spheres_for_tree = 16;  // fewer spheres: all outside, no tree
    unsigned threads = 0;                   // 0: std::thread::hardware_concurrency()
};

// The binary SAH tree; no root-to-leaf path has more than kBvhMaxDepth levels.
BinaryBvh build_binary_bvh(std::span<const Sphere> spheres, const BvhSettings& settings = {});

// The 4-wide tree over the same leaves, two ways:
//  - by cost: the lanes of every node chosen by the surface area heuristic
//    (dynamic programming over the binary tree), which fills nodes best;
//  - by levels: each node takes its binary node's grandchildren (a child
//    that is a leaf stays one lane), then while it has fewer than four
//    lanes expands the interior lane of largest surface area. Every interior
//    lane lies two binary levels down or more, which bounds the stack by
//    3 * (kBvhMaxDepth / 2) (see above).
SphereBvh collapse_by_cost(const BinaryBvh& binary);
SphereBvh collapse_by_levels(const BinaryBvh& binary);

// By cost when that tree's bvh_stack_bound is within max_stack, else by
// levels: either way within ORB_BVH_STACK_SIZE.
SphereBvh collapse_to_4_wide(const BinaryBvh& binary, int max_stack = ORB_BVH_STACK_SIZE);

// build_binary_bvh then collapse_to_4_wide.
SphereBvh build_sphere_bvh(std::span<const Sphere> spheres, const BvhSettings& settings = {});

// The most entries ordered traversal can hold on its stack for this tree:
// over every root-to-node path, the sum of (children - 1) of its interior
// nodes. Never more than ORB_BVH_STACK_SIZE for a tree built here.
int bvh_stack_bound(const SphereBvh& bvh);

// Levels of the 4-wide tree (a tree of only a root node has 1).
int bvh_depth(const SphereBvh& bvh);

// The box a sphere has in the tree: its bounds, padded for the device's
// float copy of the sphere and rounded outward to float (sphere_bvh_build.cpp).
void sphere_float_box(const Sphere& sphere, float lo[3], float hi[3]);

// Refitting (sphere_bvh_refit.cpp): the same tree over spheres that moved,
// for the frames of an animation. The topology, each leaf's spheres and the
// outside list stay; every box is recomputed from `spheres` (as many as the
// tree was built over), bottom up. The result is a correct tree for any
// motion, but a worse one the farther spheres move from where it was built.
void refit_sphere_bvh(SphereBvh& bvh, std::span<const Sphere> spheres);

// The tree's surface area heuristic cost relative to its root box: the
// expected boxes and spheres a random ray through the root tests, sum over
// nodes of area / root area times (4 box tests + the leaf spheres). A
// refitted tree's cost over its cost when built says how much it has
// degraded; 0 for an empty tree.
double bvh_sah_cost(const SphereBvh& bvh);

}  // namespace orb::render
