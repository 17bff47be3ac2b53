// Splitting a pass's samples over devices in proportion to their speed.
#pragma once

#include <vector>

namespace orb::render {

// Shares of `count` in proportion to `weights` (positive), rounded by
// largest remainder so that they add up to `count`; ties go to the earlier
// device.
std::vector<int> split_in_proportion(int count, const std::vector<double>& weights);

}  // namespace orb::render
