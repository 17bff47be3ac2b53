// Walker's alias method: picks one of n items with probability proportional
// to its weight in O(1) — one uniform number chooses a slot, the same number
// rescaled chooses the slot's item or its alias. The kernels pick the light
// for next-event estimation this way, by power, so a scene of ten thousand
// small emitters costs no more per sample than one of ten.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace orb::render {

struct AliasSlot {
    float threshold;      // keep this slot's own item when the rescaled number is below it
    std::uint32_t alias;  // otherwise take this item
};

struct AliasTable {
    std::vector<AliasSlot> slots;   // one per item
    std::vector<float> probability;  // each item's probability, weight / sum (the pdf factor of MIS)
};

// Throws std::invalid_argument for no items, a negative or non-finite weight,
// or weights that sum to zero.
AliasTable build_alias_table(std::span<const double> weights);

// The item that uniform number u in [0, 1) selects (as the kernel does it).
std::uint32_t sample_alias_table(const AliasTable& table, float u);

}  // namespace orb::render
