#include "float_limits.h"

#include <cmath>

#include "orb/scene/detail/json_text.h"
#include "orb/scene/scene_json.h"

namespace orb::detail {

bool within_magnitude(double value) { return std::fabs(value) <= kMaxSceneMagnitude; }

bool positive_in_range(double value) { return value >= kMinScenePositive && value <= kMaxSceneMagnitude; }

std::string magnitude_rule() {
    return "each component must be in [-" + format_number(kMaxSceneMagnitude) + ", " +
           format_number(kMaxSceneMagnitude) + "]";
}

std::string positive_rule() {
    return "must be in [" + format_number(kMinScenePositive) + ", " + format_number(kMaxSceneMagnitude) + "]";
}

}  // namespace orb::detail
