// The device form of a 4-wide node (bvh_node_record.h): every child box,
// decoded from its 8-bit grid as the kernels decode it, contains the child's
// float box, so traversal never misses a sphere the float boxes hold; empty
// lanes decode to boxes no ray enters; and the grid is fine enough to matter.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bvh_node_record.h"

using namespace orb::render;

namespace {

BvhChild child_box(float lo_x, float lo_y, float lo_z, float hi_x, float hi_y, float hi_z) {
    BvhChild c{};
    c.lo[0] = lo_x, c.lo[1] = lo_y, c.lo[2] = lo_z;
    c.hi[0] = hi_x, c.hi[1] = hi_y, c.hi[2] = hi_z;
    c.count = 1;
    return c;
}

// Checks every used lane of `node`'s record; returns the largest gap between
// a decoded plane and the float plane, relative to the node's extent on that axis.
double expect_contains(const BvhNode& node) {
    const orb::device::BvhNodeRecord record = bvh_node_record(node, {-1, -2, -3, -4});
    double worst = 0;
    for (int axis = 0; axis < 3; ++axis) {
        float lo = INFINITY, hi = -INFINITY;
        for (std::uint32_t k = 0; k < node.child_count; ++k) {
            lo = std::min(lo, node.children[k].lo[axis]);
            hi = std::max(hi, node.children[k].hi[axis]);
        }
        for (std::uint32_t k = 0; k < node.child_count; ++k) {
            const std::array<float, 6> box = decoded_box(record, static_cast<int>(k));
            const BvhChild& c = node.children[k];
            EXPECT_LE(box[axis], c.lo[axis]) << "lane " << k << " axis " << axis;
            EXPECT_GE(box[axis + 3], c.hi[axis]) << "lane " << k << " axis " << axis;
            const double extent = double(hi) - lo;
            if (extent > 0)
                worst = std::max({worst, (double(c.lo[axis]) - box[axis]) / extent,
                                  (double(box[axis + 3]) - c.hi[axis]) / extent});
        }
    }
    for (int k = static_cast<int>(node.child_count); k < 4; ++k) {
        const std::array<float, 6> box = decoded_box(record, k);
        for (int axis = 0; axis < 3; ++axis) EXPECT_GT(box[axis], box[axis + 3]) << "empty lane " << k;
    }
    EXPECT_EQ(record.child.x, -1);
    EXPECT_EQ(record.child.w, -4);
    return worst;
}

}  // namespace

TEST(BvhNodeRecord, DecodedBoxesContainTheChildBoxesAndAreTight) {
    std::mt19937 rng(3);
    double worst = 0;
    for (double scale : {1e-3, 1.0, 1e4, 1e7}) {
        std::uniform_real_distribution<float> pos(static_cast<float>(-scale), static_cast<float>(scale));
        std::uniform_real_distribution<float> size(0.0f, static_cast<float>(scale / 4));
        for (int trial = 0; trial < 2000; ++trial) {
            BvhNode node{};
            node.child_count = 1 + trial % 4;
            for (std::uint32_t k = 0; k < node.child_count; ++k) {
                const float x = pos(rng), y = pos(rng), z = pos(rng);
                node.children[k] = child_box(x, y, z, x + size(rng), y + size(rng), z + size(rng));
            }
            worst = std::max(worst, expect_contains(node));
        }
    }
    // Each plane moves out by at most one grid line, and 255 lines span at
    // most twice the node (the step is a power of two).
    EXPECT_LE(worst, 2.0 / 255.0 + 1e-6);
}

// Boxes of zero width, far from the origin, touching zero and at float
// subnormal scale: still contained (the grid avoids subnormals).
TEST(BvhNodeRecord, ExtremeBoxesStayContained) {
    const float tiny = std::nextafter(0.0f, 1.0f);
    BvhNode node{};
    node.child_count = 3;
    node.children[0] = child_box(1e30f, -1e30f, 0.0f, 1e30f, -1e30f, 0.0f);
    node.children[1] = child_box(-tiny, 0.0f, 1e-38f, tiny, 1e-38f, 2e-38f);
    node.children[2] = child_box(3.0f, 3.0f, 3.0f, std::nextafter(3.0f, 4.0f), 3.0f, 3.0f);
    expect_contains(node);
    BvhNode small{};
    small.child_count = 2;
    small.children[0] = child_box(-tiny, -tiny, -tiny, tiny, tiny, tiny);
    small.children[1] = child_box(1e-39f, 1e-39f, 1e-39f, 2e-39f, 2e-39f, 2e-39f);
    expect_contains(small);
}
