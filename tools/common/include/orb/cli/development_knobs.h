// The development knobs (orb/render/development_knobs.h) read from the
// environment: the one place a tool turns ORB_SIMD_LANES and the rest into
// the renderer's settings, before it renders (docs/rendering.md,
// "Development knobs").
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "orb/render/development_knobs.h"

namespace orb::cli {

// An environment variable's value, or nullptr when it is not set.
using EnvironmentLookup = std::function<const char*(const char* name)>;

// The knobs from the variables `lookup` gives. A variable set to "" counts
// as not set. Throws UsageError naming the variable, its value and what was
// expected when a value is malformed. Adds to `warnings` one line for each
// variable set that no longer does anything in a product tool
// (ORB_CAPTURE_PASS, ORB_CAPTURE_SKIP: the pass capture is in dev/ now).
render::DevelopmentKnobs parse_development_knobs(const EnvironmentLookup& lookup,
                                                 std::vector<std::string>& warnings);

// The same from this process's environment, its warnings through
// cli::warning.
render::DevelopmentKnobs development_knobs_from_environment();

}  // namespace orb::cli
