// Quantising a node's child boxes (bvh_node_record.h). Per axis the grid
// starts at the node's lower bound and steps by a power of two chosen so
// that 255 steps span the node; each child plane becomes the grid line at or
// beyond it (lo down, hi up). The kernels decode a plane as
// fma(q, step, origin), one correctly rounded operation, which the host
// repeats here with std::fma to check each decoded plane and move it a line
// further out where rounding put it inside: the decoded box always contains
// the float box, so no ray misses a sphere it would have hit.
#include "bvh_node_record.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace orb::render {
namespace {

constexpr int kLevels = 255;
// Steps, origins and decoded planes stay clear of float subnormals, which
// some devices flush to zero: every value involved is 0 or a multiple of
// 2^-123 of at least 2^-100 in magnitude.
constexpr float kSmallest = 0x1p-100f;

float decode(int q, float step, float origin) { return std::fma(static_cast<float>(q), step, origin); }

std::uint8_t byte_of(std::uint32_t word, int lane) { return static_cast<std::uint8_t>(word >> (8 * lane)); }
void set_byte(std::uint32_t& word, int lane, int q) {
    word = (word & ~(0xffu << (8 * lane))) | (static_cast<std::uint32_t>(q) << (8 * lane));
}

}  // namespace

device::BvhNodeRecord bvh_node_record(const BvhNode& node, const std::array<int, kBvhWidth>& child) {
    device::BvhNodeRecord record{};
    record.child = {child[0], child[1], child[2], child[3]};
    for (int axis = 0; axis < 3; ++axis) {
        float lo = std::numeric_limits<float>::infinity(), hi = -lo;
        for (std::uint32_t k = 0; k < node.child_count; ++k) {
            lo = std::min(lo, node.children[k].lo[axis]);
            hi = std::max(hi, node.children[k].hi[axis]);
        }
        if (lo != 0.0f && std::abs(lo) < kSmallest) lo = -kSmallest;
        const double extent = double(hi) - double(lo);
        // The smallest power of two with kLevels steps spanning the node.
        float step = kSmallest;
        while (double(step) * kLevels < extent) step *= 2.0f;
        record.origin[axis] = lo;
        record.step[axis] = step;
        std::uint32_t& lo_word = record.planes[axis];
        std::uint32_t& hi_word = record.planes[axis + 3];
        for (int k = 0; k < kBvhWidth; ++k) {
            if (static_cast<std::uint32_t>(k) >= node.child_count) {
                // Empty lane: lo on the top line, hi on the bottom one, an
                // inverted box (step > 0), entered after it is left.
                set_byte(lo_word, k, kLevels);
                set_byte(hi_word, k, 0);
                continue;
            }
            const BvhChild& c = node.children[k];
            int q_lo = std::clamp(static_cast<int>(std::floor((double(c.lo[axis]) - lo) / step)), 0, kLevels);
            while (q_lo > 0 && decode(q_lo, step, lo) > c.lo[axis]) --q_lo;
            int q_hi = std::clamp(static_cast<int>(std::ceil((double(c.hi[axis]) - lo) / step)), 0, kLevels);
            // Line kLevels lies at or beyond the node's hi: lo + 255 step >= hi exactly,
            // and rounding to nearest keeps it there.
            while (q_hi < kLevels && decode(q_hi, step, lo) < c.hi[axis]) ++q_hi;
            set_byte(lo_word, k, q_lo);
            set_byte(hi_word, k, q_hi);
        }
    }
    return record;
}

std::array<float, 6> decoded_box(const device::BvhNodeRecord& record, int lane) {
    std::array<float, 6> box{};
    for (int axis = 0; axis < 3; ++axis) {
        box[axis] = decode(byte_of(record.planes[axis], lane), record.step[axis], record.origin[axis]);
        box[axis + 3] = decode(byte_of(record.planes[axis + 3], lane), record.step[axis], record.origin[axis]);
    }
    return box;
}

}  // namespace orb::render
