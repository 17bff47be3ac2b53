// Vec3 and the small vector maths every layer shares (the camera's frame,
// the device layout, the EXR camera matrices, the importers). The functions
// live in namespace orb::vec3 so that a file's own helpers of the same name
// never make a call ambiguous.
#pragma once

#include <array>
#include <cmath>

namespace orb {

using Vec3 = std::array<double, 3>;

namespace vec3 {

inline Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// sqrt of the squares' sum rather than std::hypot: scene coordinates are at
// most 1e18 (kMaxSceneMagnitude), whose squares do not overflow, and the
// camera matrices stored in EXRs keep the bits they were written with.
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
// Each component divided by the length (not multiplied by its reciprocal:
// one rounding per component). NaN for the zero vector; callers check.
inline Vec3 normalized(const Vec3& a) {
    const double l = length(a);
    return {a[0] / l, a[1] / l, a[2] / l};
}

}  // namespace vec3
}  // namespace orb
