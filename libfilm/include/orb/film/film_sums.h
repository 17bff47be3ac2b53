// A Sum channel's sums as the film keeps them: 64-bit integers counting the
// units of the channel's `units` column (film_channels.h). Integer addition
// is exact and associative, so a pixel's sum is the same bits however its
// samples were grouped: passes, devices, resumed runs, merged slices
// (docs/design/exact-film-sums.md). The device converts each sample once
// (kernels/film.cl); these are the host's side of the same rules.
#pragma once

#include <cstdint>
#include <limits>

#include "orb/tables/film_channels.h"

namespace orb::film {

// a + b, stopping at the largest (smallest) int64 instead of wrapping, as
// OpenCL's add_sat: for sums of non-negative units this is min(a + b, max),
// which is associative, so a saturated sum is saturated in every grouping.
constexpr Sum add_sums(Sum a, Sum b)
{
    Sum sum = 0;
    if (__builtin_add_overflow(a, b, &sum)) return b > 0 ? std::numeric_limits<Sum>::max() : std::numeric_limits<Sum>::min();
    return sum;
}

// The value a sum of `units` stands for: sum * unit_value(units), in double
// (exact up to 2^53 units, then rounded once, deterministically).
inline double sum_value(Units units, Sum sum) { return static_cast<double>(sum) * unit_value(units); }

// A sum's value (mean * count, say) in whole units, rounded to the nearest;
// non-finite or out-of-range values stop at the range's ends (0 and
// kSumRangeEnd for Fixed and Count). For sums recovered from files that
// hold means only: within a float rounding of the original, not exact.
Sum sum_units(Units units, double value);

}  // namespace orb::film
