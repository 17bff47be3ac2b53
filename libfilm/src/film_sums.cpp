#include "orb/film/film_sums.h"

#include <algorithm>
#include <cmath>

namespace orb::film {

Sum sum_units(Units units, double value)
{
    // Clamped into the range (NaN to its low end), then rounded to the nearest unit.
    const double high = static_cast<double>(kSumRangeEnd) * unit_value(units);
    const double low = units == Units::SignedFixed ? -high : 0.0;
    if (!(value >= low)) value = low;
    value = std::min(value, high);
    return static_cast<Sum>(std::nearbyint(value / unit_value(units)));
}

}  // namespace orb::film
