// A 4-wide BVH node as the device stores it (BvhNodeRecord, device_types.h):
// the children's boxes on an 8-bit grid spanning the node, rounded outward.
#pragma once

#include <array>

#include "orb/kernels/device_types.h"
#include "sphere_bvh.h"

namespace orb::render {

// The record of `node`, lane k being node.children[k] with descriptor
// child[k] (BvhNodeRecord::child); lanes past child_count are empty.
device::BvhNodeRecord bvh_node_record(const BvhNode& node, const std::array<int, kBvhWidth>& child);

// Lane `lane`'s box as the kernels decode it: lo x, y, z, hi x, y, z.
std::array<float, 6> decoded_box(const device::BvhNodeRecord& record, int lane);

}  // namespace orb::render
