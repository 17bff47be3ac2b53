#include "alias_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace orb::render {

AliasTable build_alias_table(std::span<const double> weights) {
    const std::size_t n = weights.size();
    if (n == 0) throw std::invalid_argument("alias table: no items");
    double sum = 0.0;
    for (double w : weights) {
        if (!(w >= 0.0) || !std::isfinite(w)) throw std::invalid_argument("alias table: weights must be finite and >= 0");
        sum += w;
    }
    if (!(sum > 0.0)) throw std::invalid_argument("alias table: weights sum to zero");

    AliasTable table;
    table.slots.resize(n);
    table.probability.resize(n);
    // Vose's construction: scaled weights n * p; slots under 1 are topped up
    // from slots over 1. Worked in double, stored in float.
    std::vector<double> scaled(n);
    std::vector<std::uint32_t> small, large;
    for (std::size_t i = 0; i < n; ++i) {
        table.probability[i] = static_cast<float>(weights[i] / sum);
        scaled[i] = weights[i] / sum * static_cast<double>(n);
        (scaled[i] < 1.0 ? small : large).push_back(static_cast<std::uint32_t>(i));
    }
    while (!small.empty() && !large.empty()) {
        const std::uint32_t s = small.back(), l = large.back();
        small.pop_back();
        table.slots[s] = {static_cast<float>(scaled[s]), l};
        scaled[l] -= 1.0 - scaled[s];
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // What is left is 1 up to rounding: keep it.
    for (std::uint32_t i : small) table.slots[i] = {1.0f, i};
    for (std::uint32_t i : large) table.slots[i] = {1.0f, i};
    return table;
}

std::uint32_t sample_alias_table(const AliasTable& table, float u) {
    const auto n = static_cast<std::uint32_t>(table.slots.size());
    const float scaled = u * static_cast<float>(n);
    const std::uint32_t slot = std::min(static_cast<std::uint32_t>(scaled), n - 1);
    const float rest = scaled - static_cast<float>(slot);
    const AliasSlot& s = table.slots[slot];
    return rest < s.threshold ? slot : s.alias;
}

}  // namespace orb::render
