// Small affine-transform and quaternion helpers shared by the animation
// evaluator and the glTF importer. Matrices are column-major (glTF order):
// element (row r, column c) is m[c * 4 + r].
#pragma once

#include <array>
#include <cmath>

#include "orb/scene/animation.h"

namespace orb::detail {

inline Matrix4 multiply(const Matrix4& a, const Matrix4& b) {
    Matrix4 m{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            double sum = 0.0;
            for (int k = 0; k < 4; ++k) sum += a[k * 4 + r] * b[c * 4 + k];
            m[c * 4 + r] = sum;
        }
    return m;
}

inline Quaternion normalized(const Quaternion& q) {
    const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(length > 0.0) || !std::isfinite(length)) return {0.0, 0.0, 0.0, 1.0};
    return {q[0] / length, q[1] / length, q[2] / length, q[3] / length};
}

// T * R * S, the glTF node transform.
inline Matrix4 trs_matrix(const AnimVec3& t, const Quaternion& rotation, const AnimVec3& s) {
    const Quaternion q = normalized(rotation);
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double r00 = 1 - 2 * (y * y + z * z), r01 = 2 * (x * y - z * w), r02 = 2 * (x * z + y * w);
    const double r10 = 2 * (x * y + z * w), r11 = 1 - 2 * (x * x + z * z), r12 = 2 * (y * z - x * w);
    const double r20 = 2 * (x * z - y * w), r21 = 2 * (y * z + x * w), r22 = 1 - 2 * (x * x + y * y);
    return {r00 * s[0], r10 * s[0], r20 * s[0], 0,  //
            r01 * s[1], r11 * s[1], r21 * s[1], 0,  //
            r02 * s[2], r12 * s[2], r22 * s[2], 0,  //
            t[0],       t[1],       t[2],       1};
}

inline AnimVec3 transform_point(const Matrix4& m, const AnimVec3& p) {
    return {m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12], m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
            m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]};
}

inline AnimVec3 transform_direction(const Matrix4& m, const AnimVec3& d) {
    return {m[0] * d[0] + m[4] * d[1] + m[8] * d[2], m[1] * d[0] + m[5] * d[1] + m[9] * d[2],
            m[2] * d[0] + m[6] * d[1] + m[10] * d[2]};
}

// Lengths of the images of the x, y and z unit vectors: the axis scales.
inline AnimVec3 axis_scales(const Matrix4& m) {
    AnimVec3 s{};
    for (int c = 0; c < 3; ++c)
        s[c] = std::sqrt(m[c * 4] * m[c * 4] + m[c * 4 + 1] * m[c * 4 + 1] + m[c * 4 + 2] * m[c * 4 + 2]);
    return s;
}

inline double largest_axis_scale(const Matrix4& m) {
    const AnimVec3 s = axis_scales(m);
    return std::fmax(s[0], std::fmax(s[1], s[2]));
}

// Spherical linear interpolation along the shorter arc (the glTF rule for
// rotation channels); falls back to normalised lerp when the ends nearly meet.
inline Quaternion slerp(const Quaternion& a, Quaternion b, double s) {
    double cosine = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    if (cosine < 0.0) {
        for (double& c : b) c = -c;
        cosine = -cosine;
    }
    double wa = 1.0 - s, wb = s;
    if (cosine < 1.0 - 1e-12) {
        const double angle = std::acos(std::fmin(cosine, 1.0));
        const double sine = std::sin(angle);
        wa = std::sin((1.0 - s) * angle) / sine;
        wb = std::sin(s * angle) / sine;
    }
    return normalized({wa * a[0] + wb * b[0], wa * a[1] + wb * b[1], wa * a[2] + wb * b[2], wa * a[3] + wb * b[3]});
}

inline double dot3(const AnimVec3& a, const AnimVec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double length3(const AnimVec3& a) { return std::sqrt(dot3(a, a)); }

}  // namespace orb::detail
