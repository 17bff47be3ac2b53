// The checks and wording for numbers the renderer's 32-bit floats cannot
// hold, shared by the scene and animation validators. The limits themselves
// are in orb/scene/scene_json.h (docs/scene-format.md, "Limits").
#pragma once

#include <string>

namespace orb::detail {

// Ends every such message, before the offending value.
inline constexpr const char* kFloatReason = " (the renderer computes in 32-bit floats), got ";

bool within_magnitude(double value);   // |value| <= kMaxSceneMagnitude; false for NaN
bool positive_in_range(double value);  // kMinScenePositive <= value <= kMaxSceneMagnitude

std::string magnitude_rule();  // "each component must be in [-1e+18, 1e+18]"
std::string positive_rule();   // "must be in [1e-18, 1e+18]"

}  // namespace orb::detail
