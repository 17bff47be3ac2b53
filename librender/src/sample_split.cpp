#include "sample_split.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace orb::render {

std::vector<int> split_in_proportion(int count, const std::vector<double>& weights)
{
    if (weights.empty()) throw std::invalid_argument("no devices to split samples over");
    double total = 0;
    for (double w : weights) {
        if (!(w > 0) || !std::isfinite(w)) throw std::invalid_argument("device weights must be positive");
        total += w;
    }
    std::vector<int> shares(weights.size(), 0);
    std::vector<std::pair<double, std::size_t>> remainders;
    int given = 0;
    for (std::size_t d = 0; d < weights.size(); ++d) {
        const double exact = count * (weights[d] / total);
        shares[d] = std::min(count - given, static_cast<int>(std::floor(exact)));
        given += shares[d];
        remainders.push_back({exact - shares[d], d});
    }
    std::stable_sort(remainders.begin(), remainders.end(), [](auto a, auto b) { return a.first > b.first; });
    for (std::size_t i = 0; given < count; ++i, ++given) shares[remainders[i % remainders.size()].second] += 1;
    return shares;
}

}  // namespace orb::render
