// Recognising tessellated spheres (docs/gltf.md, "Sphere detection").
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "gltf_internal.h"

namespace orb::gltf {
namespace {

// A face whose centroid is further inside than this fraction of the radius
// is too coarse to stand for a sphere. A regular icosahedron's faces sit
// 20.5% inside its circumsphere and a cube's 42%, so both are rejected,
// while a Blender ico sphere (2 subdivisions: 5%) or UV sphere passes.
constexpr double kMaxFaceSag = 0.2;
// The vertices' bounding-box centre may be this far (relative to the radius)
// from the fitted centre: a whole sphere has it at the centre (a UV sphere
// with an odd number of segments up to ~10% off), a hemisphere at 50%.
constexpr double kMaxBoxOffset = 0.25;
// An open part is still a sphere when its triangles, seen from the centre,
// wrap the whole 4 pi steradians within this fraction (a closed
// tessellation wraps it exactly; a hemisphere covers half).
constexpr double kSolidAngleTolerance = 1e-3;

struct Box {
    AnimVec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                std::numeric_limits<double>::infinity()};
    AnimVec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                -std::numeric_limits<double>::infinity()};
    void add(const AnimVec3& p) {
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], p[c]);
            hi[c] = std::max(hi[c], p[c]);
        }
    }
    AnimVec3 center() const { return {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2}; }
    double extent() const { return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}); }
};

double distance(const AnimVec3& a, const AnimVec3& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// Solves the 4x4 system in place by Gaussian elimination with partial
// pivoting; false when it is (nearly) singular, i.e. the points are coplanar.
bool solve4(std::array<std::array<double, 5>, 4>& m, std::array<double, 4>& x) {
    double scale = 0.0;
    for (const auto& row : m)
        for (int c = 0; c < 4; ++c) scale = std::max(scale, std::fabs(row[c]));
    if (!(scale > 0)) return false;
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 4; ++r)
            if (std::fabs(m[r][col]) > std::fabs(m[pivot][col])) pivot = r;
        if (std::fabs(m[pivot][col]) < 1e-10 * scale) return false;
        std::swap(m[col], m[pivot]);
        for (int r = col + 1; r < 4; ++r) {
            const double f = m[r][col] / m[col][col];
            for (int c = col; c < 5; ++c) m[r][c] -= f * m[col][c];
        }
    }
    for (int r = 3; r >= 0; --r) {
        double sum = m[r][4];
        for (int c = r + 1; c < 4; ++c) sum -= m[r][c] * x[c];
        x[r] = sum / m[r][r];
    }
    return true;
}

// Algebraic least-squares sphere: |p|^2 = 2 c.p + k, in coordinates centred
// on the bounding box and scaled to unit size for conditioning.
std::optional<FittedSphere> least_squares_sphere(const std::vector<AnimVec3>& points, const Box& box) {
    const AnimVec3 origin = box.center();
    const double unit = box.extent();
    if (!(unit > 0) || !std::isfinite(unit)) return std::nullopt;
    std::array<std::array<double, 5>, 4> normal{};
    for (const AnimVec3& p : points) {
        const double x = (p[0] - origin[0]) / unit, y = (p[1] - origin[1]) / unit, z = (p[2] - origin[2]) / unit;
        const std::array<double, 4> row{2 * x, 2 * y, 2 * z, 1.0};
        const double rhs = x * x + y * y + z * z;
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) normal[i][j] += row[i] * row[j];
            normal[i][4] += row[i] * rhs;
        }
    }
    std::array<double, 4> solution{};
    if (!solve4(normal, solution)) return std::nullopt;
    const double r2 = solution[3] + solution[0] * solution[0] + solution[1] * solution[1] + solution[2] * solution[2];
    if (!(r2 > 0)) return std::nullopt;
    FittedSphere sphere;
    for (int c = 0; c < 3; ++c) sphere.center[c] = origin[c] + solution[c] * unit;
    sphere.radius = std::sqrt(r2) * unit;
    return sphere;
}

}  // namespace

std::optional<FittedSphere> fit_sphere(const std::vector<AnimVec3>& points,
                                       const std::vector<std::array<std::uint32_t, 3>>& triangles, double tolerance) {
    if (points.size() < 4 || triangles.empty()) return std::nullopt;
    Box box;
    for (const AnimVec3& p : points) box.add(p);
    std::optional<FittedSphere> fit = least_squares_sphere(points, box);
    if (!fit) return std::nullopt;
    const double r = fit->radius;
    // Refine the radius to the mean distance, then demand every vertex be close.
    double mean = 0.0;
    for (const AnimVec3& p : points) mean += distance(p, fit->center);
    fit->radius = mean / double(points.size());
    for (const AnimVec3& p : points)
        if (std::fabs(distance(p, fit->center) - fit->radius) > tolerance * fit->radius) return std::nullopt;
    if (distance(box.center(), fit->center) > kMaxBoxOffset * r) return std::nullopt;
    for (const auto& t : triangles) {
        AnimVec3 centroid{};
        for (std::uint32_t v : t)
            for (int c = 0; c < 3; ++c) centroid[c] += points[v][c] / 3.0;
        if (distance(centroid, fit->center) < (1.0 - kMaxFaceSag) * fit->radius) return std::nullopt;
    }
    if (!is_closed(triangles)) {
        const double full = 4 * std::numbers::pi;
        if (std::fabs(solid_angle_seen_from(fit->center, points, triangles) - full) > kSolidAngleTolerance * full)
            return std::nullopt;
    }
    return fit;
}

FittedSphere bounding_sphere(const std::vector<AnimVec3>& points) {
    Box box;
    for (const AnimVec3& p : points) box.add(p);
    FittedSphere sphere;
    if (points.empty()) return sphere;
    sphere.center = box.center();
    for (const AnimVec3& p : points) sphere.radius = std::max(sphere.radius, distance(p, sphere.center));
    return sphere;
}

std::vector<std::array<std::uint32_t, 3>> triangles_of(int mode, const std::vector<std::uint32_t>& indices) {
    std::vector<std::array<std::uint32_t, 3>> triangles;
    const std::size_t n = indices.size();
    if (mode == TINYGLTF_MODE_TRIANGLES || mode == -1) {
        for (std::size_t i = 0; i + 2 < n; i += 3) triangles.push_back({indices[i], indices[i + 1], indices[i + 2]});
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 0; i + 2 < n; ++i) triangles.push_back({indices[i], indices[i + 1], indices[i + 2]});
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (std::size_t i = 1; i + 1 < n; ++i) triangles.push_back({indices[0], indices[i], indices[i + 1]});
    }
    return triangles;
}

}  // namespace orb::gltf
