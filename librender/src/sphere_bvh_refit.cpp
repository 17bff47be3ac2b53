// Refitting a sphere BVH to moved spheres, and the SAH cost that says when a
// refitted tree has degraded enough to rebuild (sphere_bvh.h).
#include <algorithm>
#include <cstddef>
#include <limits>

#include "sphere_bvh.h"

namespace orb::render {
namespace {

struct Bounds {
    float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                   std::numeric_limits<float>::infinity()};
    float hi[3] = {-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                   -std::numeric_limits<float>::infinity()};

    void grow(const float other_lo[3], const float other_hi[3])
    {
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], other_lo[a]);
            hi[a] = std::max(hi[a], other_hi[a]);
        }
    }
};

double area(const float lo[3], const float hi[3])
{
    const double x = double(hi[0]) - lo[0], y = double(hi[1]) - lo[1], z = double(hi[2]) - lo[2];
    return 2.0 * (x * y + y * z + z * x);
}

}  // namespace

void refit_sphere_bvh(SphereBvh& bvh, std::span<const Sphere> spheres)
{
    // Children come after their parent (depth-first order), so going through
    // the nodes backwards meets every interior child's node refitted already.
    for (std::size_t i = bvh.nodes.size(); i-- > 0;) {
        BvhNode& node = bvh.nodes[i];
        for (std::uint32_t k = 0; k < node.child_count; ++k) {
            BvhChild& child = node.children[k];
            Bounds bounds;
            if (child.leaf()) {
                for (std::uint32_t j = 0; j < child.count; ++j) {
                    float lo[3], hi[3];
                    sphere_float_box(spheres[bvh.order[child.first + j]], lo, hi);
                    bounds.grow(lo, hi);
                }
            } else {
                const BvhNode& below = bvh.nodes[child.first];
                for (std::uint32_t j = 0; j < below.child_count; ++j)
                    bounds.grow(below.children[j].lo, below.children[j].hi);
            }
            std::copy(bounds.lo, bounds.lo + 3, child.lo);
            std::copy(bounds.hi, bounds.hi + 3, child.hi);
        }
    }
}

double bvh_sah_cost(const SphereBvh& bvh)
{
    if (bvh.nodes.empty()) return 0.0;
    Bounds root;
    for (std::uint32_t k = 0; k < bvh.nodes[0].child_count; ++k)
        root.grow(bvh.nodes[0].children[k].lo, bvh.nodes[0].children[k].hi);
    const double root_area = area(root.lo, root.hi);
    if (!(root_area > 0.0)) return 0.0;
    // The root is always visited: its four box tests; each child is entered
    // with probability area(child) / area(root): its four box tests, or its
    // spheres for a leaf.
    double cost = kBvhWidth;
    for (const BvhNode& node : bvh.nodes)
        for (std::uint32_t k = 0; k < node.child_count; ++k) {
            const BvhChild& child = node.children[k];
            cost += area(child.lo, child.hi) / root_area * (child.leaf() ? double(child.count) : double(kBvhWidth));
        }
    return cost;
}

}  // namespace orb::render
