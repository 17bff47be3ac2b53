// The scene's environment as device tables and parameters (device_types.h:
// EnvironmentTexel, EnvironmentCdf, EnvironmentParams).
#pragma once

#include <vector>

#include "orb/tables/device_types.h"
#include "orb/scene/scene.h"

namespace orb::render {

struct EnvironmentLayout {
    std::vector<device::EnvironmentTexel> texels;
    std::vector<device::EnvironmentCdf> cdf;
    device::EnvironmentParams params{};  // width 0: no environment; light_probability left to the light table
    // Whether the environment sends any light, and so takes part in light picking.
    bool emits = false;
};

// A uniform colour is a single texel covering the whole sphere (sampled
// uniformly, pdf 1 / 4 pi); a map is its texels times the intensity. An
// environment that sends no light (black, intensity 0) is laid out as none.
// Throws std::invalid_argument for a map whose texels are not attached
// (orb::exr::load_environment_map) or do not fill width x height.
EnvironmentLayout layout_environment(const Environment& environment);

}  // namespace orb::render
