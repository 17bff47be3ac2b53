// The binary SAH tree collapsed into the 4-wide tree the kernels traverse
// (sphere_bvh.h), and the bounds its traversal relies on.
#include <algorithm>
#include <array>
#include <limits>

#include "sphere_bvh.h"

namespace orb::render {
namespace {

// Appends 4-wide nodes to `out`, depth first, given for each binary
// interior node the binary nodes that become its 4-wide node's lanes.
template <typename LanesOf>
std::uint32_t emit(const BinaryBvh& binary, SphereBvh& out, std::uint32_t index, const LanesOf& lanes_of) {
    const auto slot = static_cast<std::uint32_t>(out.nodes.size());
    out.nodes.emplace_back();
    const std::vector<std::uint32_t> lanes = lanes_of(index);
    out.nodes[slot].child_count = static_cast<std::uint32_t>(lanes.size());
    for (std::size_t k = 0; k < lanes.size(); ++k) {
        const BinaryBvhNode& node = binary.nodes[lanes[k]];
        BvhChild child{};
        std::copy(node.lo, node.lo + 3, child.lo);
        std::copy(node.hi, node.hi + 3, child.hi);
        child.count = node.count;
        child.first = node.leaf() ? node.first : emit(binary, out, lanes[k], lanes_of);  // `out.nodes` may grow here
        out.nodes[slot].children[k] = child;
    }
    return slot;
}

SphereBvh with_leaves_of(const BinaryBvh& binary) {
    SphereBvh bvh;
    bvh.order = binary.order;
    bvh.outside = binary.outside;
    bvh.nodes.reserve(binary.nodes.size() / 2 + 1);
    return bvh;
}

// The surface area heuristic's choice of lanes (after Ylitie, Karras and
// Laine, "Efficient incoherent ray traversal on GPUs through compressed wide
// BVHs", HPG 2017): a ray that enters a node's box tests its four lanes'
// boxes (cost kNodeCost), one that enters a leaf's box tests its packet
// (kLeafCost), and a ray enters a box with a chance proportional to its
// area. For each binary node and i = 1..4, cost[i] is the least cost of its
// subtree cut into at most i lanes; dynamic programming from the leaves up
// finds the cut of every 4-wide node that minimises the tree's total.
class CostCollapse {
public:
    explicit CostCollapse(const BinaryBvh& binary) : binary_(binary), best_(binary.nodes.size()) {
        // Children follow their parents, so a reverse pass meets children first.
        for (std::size_t n = binary.nodes.size(); n-- > 0;) solve(static_cast<std::uint32_t>(n));
    }

    // The lanes of the 4-wide node made from interior binary node `index`.
    std::vector<std::uint32_t> lanes_of(std::uint32_t index) const {
        std::vector<std::uint32_t> lanes;
        const BinaryBvhNode& node = binary_.nodes[index];
        if (node.leaf()) return {index};  // the root of a tree of one leaf
        const int left = best_[index].node_split;
        cut(node.first, left, lanes);
        cut(node.first + 1, kBvhWidth - left, lanes);
        return lanes;
    }

private:
    static constexpr double kNodeCost = 1.0;
    static constexpr double kLeafCost = 1.0;

    struct Best {
        std::array<double, kBvhWidth + 1> cost{};  // [i]: subtree in at most i lanes ([0] unused)
        // [i]: 0 when the best cut into at most i lanes is this node as one
        // lane; else the lanes its left child gets (the right gets i - that)
        std::array<std::int8_t, kBvhWidth + 1> split{};
        // As a 4-wide node: the lanes its left child's subtree gets (the rest go right).
        std::int8_t node_split = 0;
    };

    static double area(const BinaryBvhNode& node) {
        const double x = double(node.hi[0]) - node.lo[0], y = double(node.hi[1]) - node.lo[1],
                     z = double(node.hi[2]) - node.lo[2];
        return 2.0 * (x * y + y * z + z * x);
    }

    void solve(std::uint32_t n) {
        const BinaryBvhNode& node = binary_.nodes[n];
        Best& best = best_[n];
        if (node.leaf()) {
            best.cost.fill(area(node) * kLeafCost);
            best.split.fill(0);
            return;
        }
        const Best& left = best_[node.first];
        const Best& right = best_[node.first + 1];
        // forest[i], forest_split[i]: both children's subtrees in at most i lanes together.
        std::array<double, kBvhWidth + 1> forest{};
        std::array<std::int8_t, kBvhWidth + 1> forest_split{};
        for (int i = 2; i <= kBvhWidth; ++i) {
            forest[i] = std::numeric_limits<double>::infinity();
            for (int k = 1; k < i; ++k) {
                const double c = left.cost[k] + right.cost[i - k];
                if (c < forest[i]) {
                    forest[i] = c;
                    forest_split[i] = static_cast<std::int8_t>(k);
                }
            }
        }
        // As one lane, this node is a 4-wide node over its best four-lane forest.
        best.cost[1] = area(node) * kNodeCost + forest[kBvhWidth];
        best.split[1] = 0;
        best.node_split = forest_split[kBvhWidth];
        for (int i = 2; i <= kBvhWidth; ++i) {
            if (forest[i] < best.cost[i - 1]) {
                best.cost[i] = forest[i];
                best.split[i] = forest_split[i];
            } else {
                best.cost[i] = best.cost[i - 1];
                best.split[i] = best.split[i - 1];
            }
        }
    }

    // Appends the lanes of the subtree of `n` cut into at most i lanes.
    void cut(std::uint32_t n, int i, std::vector<std::uint32_t>& lanes) const {
        const int split = best_[n].split[i];
        if (split == 0) {
            lanes.push_back(n);
            return;
        }
        const BinaryBvhNode& node = binary_.nodes[n];
        cut(node.first, split, lanes);
        cut(node.first + 1, i - split, lanes);
    }

    const BinaryBvh& binary_;
    std::vector<Best> best_;
};

// The level rule: a node's lanes are its binary grandchildren (a child that
// is a leaf stays one lane), so that every interior lane lies at least two
// binary levels below, which bounds the stack (sphere_bvh.h); free lanes
// then go to the interior lane of largest area.
std::vector<std::uint32_t> level_lanes(const BinaryBvh& binary, std::uint32_t index) {
    const BinaryBvhNode& node = binary.nodes[index];
    if (node.leaf()) return {index};  // the root of a tree of one leaf
    std::vector<std::uint32_t> lanes;
    for (std::uint32_t child : {node.first, node.first + 1}) {
        const BinaryBvhNode& c = binary.nodes[child];
        if (c.leaf()) {
            lanes.push_back(child);
        } else {
            lanes.push_back(c.first);
            lanes.push_back(c.first + 1);
        }
    }
    auto area = [&](std::uint32_t n) {
        const BinaryBvhNode& b = binary.nodes[n];
        const double x = double(b.hi[0]) - b.lo[0], y = double(b.hi[1]) - b.lo[1], z = double(b.hi[2]) - b.lo[2];
        return x * y + y * z + z * x;
    };
    while (lanes.size() < static_cast<std::size_t>(kBvhWidth)) {
        auto largest = lanes.end();
        for (auto it = lanes.begin(); it != lanes.end(); ++it)
            if (!binary.nodes[*it].leaf() && (largest == lanes.end() || area(*it) > area(*largest))) largest = it;
        if (largest == lanes.end()) break;
        const std::uint32_t expanded = binary.nodes[*largest].first;
        *largest = expanded;
        lanes.insert(largest + 1, expanded + 1);
    }
    return lanes;
}

}  // namespace

SphereBvh collapse_by_levels(const BinaryBvh& binary) {
    SphereBvh bvh = with_leaves_of(binary);
    if (!binary.nodes.empty())
        emit(binary, bvh, 0, [&](std::uint32_t index) { return level_lanes(binary, index); });
    return bvh;
}

SphereBvh collapse_by_cost(const BinaryBvh& binary) {
    SphereBvh bvh = with_leaves_of(binary);
    if (binary.nodes.empty()) return bvh;
    const CostCollapse cost(binary);
    emit(binary, bvh, 0, [&](std::uint32_t index) { return cost.lanes_of(index); });
    return bvh;
}

SphereBvh collapse_to_4_wide(const BinaryBvh& binary, int max_stack) {
    SphereBvh bvh = collapse_by_cost(binary);
    if (bvh_stack_bound(bvh) <= max_stack) return bvh;
    return collapse_by_levels(binary);
}

SphereBvh build_sphere_bvh(std::span<const Sphere> spheres, const BvhSettings& settings) {
    return collapse_to_4_wide(build_binary_bvh(spheres, settings));
}

int bvh_stack_bound(const SphereBvh& bvh) {
    if (bvh.nodes.empty()) return 0;
    // Children follow their parents, so one pass from the root down carries
    // each node's sum (its path's deferrals before it) to its children.
    std::vector<int> before(bvh.nodes.size(), 0);
    int bound = 0;
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
        const BvhNode& node = bvh.nodes[i];
        const int after = before[i] + static_cast<int>(node.child_count) - 1;
        bound = std::max(bound, after);
        for (std::uint32_t k = 0; k < node.child_count; ++k)
            if (!node.children[k].leaf()) before.at(node.children[k].first) = after;
    }
    return bound;
}

int bvh_depth(const SphereBvh& bvh) {
    if (bvh.nodes.empty()) return 0;
    std::vector<int> level(bvh.nodes.size(), 1);
    int depth = 1;
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
        const BvhNode& node = bvh.nodes[i];
        depth = std::max(depth, level[i]);
        for (std::uint32_t k = 0; k < node.child_count; ++k)
            if (!node.children[k].leaf()) level.at(node.children[k].first) = level[i] + 1;
    }
    return depth;
}

}  // namespace orb::render
