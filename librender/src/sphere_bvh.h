// A bounding volume hierarchy over spheres, built on the host for the
// kernels' closest-hit and shadow-ray traversal (docs/rendering.md).
//
// Binary tree, children adjacent (an interior node's right child is its left
// child + 1), depth-first order, leaves of at most four spheres so that one
// leaf is one packet of PoCL's four-wide intersection. Boxes are rounded
// outward to float, so a float ray test never misses a sphere the double
// box contains.
//
// Spheres that dwarf the scene (a floor of radius 10^4 beside grains of
// radius 0.1, the walls of the Cornell box) would enlarge every box they
// share: they stay outside the tree and every ray tests them directly, as
// do all spheres of a scene too small for a tree to pay.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "orb/scene/scene.h"

namespace orb::render {

struct BvhNode {
    float lo[3];
    std::uint32_t first;  // interior: left child's index; leaf: first entry of SphereBvh::order
    float hi[3];
    std::uint32_t count;  // 0 for an interior node; a leaf's sphere count (1..kBvhMaxLeafSize)
};
static_assert(sizeof(BvhNode) == 32, "two 16-byte loads per node on the device");

inline constexpr int kBvhMaxLeafSize = 4;
inline constexpr int kBvhMaxDepth = 64;  // no root-to-leaf path is longer (the device's stack size)

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

SphereBvh build_sphere_bvh(std::span<const Sphere> spheres, const BvhSettings& settings = {});

}  // namespace orb::render
