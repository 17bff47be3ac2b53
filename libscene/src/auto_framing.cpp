#include "orb/scene/auto_framing.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

namespace orb {
namespace {

using vec3::cross;
using vec3::dot;

// std::hypot rather than vec3::normalized: the imported cameras (and so the
// content hashes of imported scenes) keep the bits they had.
Vec3 unit(const Vec3& v) {
    const double length = std::hypot(v[0], v[1], v[2]);
    return {v[0] / length, v[1] / length, v[2] / length};
}

// The k-th smallest and k-th largest of `values` (reordered).
std::pair<double, double> trimmed_bounds(std::vector<double>& values, std::size_t k) {
    const auto low = values.begin() + static_cast<std::ptrdiff_t>(k);
    std::nth_element(values.begin(), low, values.end());
    const double lo = *low;
    const auto high = values.end() - 1 - static_cast<std::ptrdiff_t>(k);
    std::nth_element(values.begin(), high, values.end());
    return {lo, *high};
}

}  // namespace

bool StrayBounds::keeps(const Vec3& p) const {
    for (int c = 0; c < 3; ++c)
        if (!(p[c] >= lo[c] && p[c] <= hi[c])) return false;
    return true;
}

StrayBounds stray_bounds(const std::vector<Vec3>& points) {
    // The core box: the trimmed bounds per axis (all of them under 100
    // points), grown by a tenth of its largest side to keep the tails.
    const std::size_t k = points.size() / kFramingOutlierDivisor;
    StrayBounds b;
    std::vector<double> axis(points.size());
    for (int c = 0; c < 3; ++c) {
        for (std::size_t j = 0; j < points.size(); ++j) axis[j] = points[j][c];
        std::tie(b.lo[c], b.hi[c]) = trimmed_bounds(axis, k);
    }
    const double reach = kFramingStrayReach * std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]});
    for (int c = 0; c < 3; ++c) {
        b.lo[c] -= reach;
        b.hi[c] += reach;
    }
    return b;
}

std::optional<Framing> frame_spheres(const std::vector<Sphere>& spheres, const FramingView& view,
                                     const std::function<bool(std::size_t)>& skip) {
    std::vector<std::size_t> counted;
    counted.reserve(spheres.size());
    for (std::size_t i = 0; i < spheres.size(); ++i)
        if (!skip || !skip(i)) counted.push_back(i);
    if (counted.empty()) return std::nullopt;

    std::vector<Vec3> centres(counted.size());
    for (std::size_t j = 0; j < counted.size(); ++j) centres[j] = spheres[counted[j]].center;
    const StrayBounds strays = stray_bounds(centres);
    centres = {};
    const auto kept = [&strays](const Sphere& s) { return strays.keeps(s.center); };

    Framing f;
    for (std::size_t i : counted) {
        const Sphere& s = spheres[i];
        if (!kept(s)) continue;
        for (int c = 0; c < 3; ++c) {
            const double a = s.center[c] - s.radius, b = s.center[c] + s.radius;
            f.lo[c] = f.framed == 0 ? a : std::min(f.lo[c], a);
            f.hi[c] = f.framed == 0 ? b : std::max(f.hi[c], b);
        }
        ++f.framed;
    }
    for (int c = 0; c < 3; ++c) f.target[c] = (f.lo[c] + f.hi[c]) / 2;

    // The camera's frame: back towards the camera, right and up across the image.
    const Vec3 back = unit(view.toward_camera);
    const Vec3 forward{-back[0], -back[1], -back[2]};
    const Vec3 right = unit(cross(forward, view.up));
    const Vec3 up = cross(right, forward);
    // The field of view narrowed by the margin: a sphere tangent to its side
    // planes projects to a disc that touches 1 / (1 + margin) of the half-image.
    const double tan_v = std::tan(view.vfov_deg * std::numbers::pi / 360.0) / (1.0 + kFramingMargin);
    const double tan_h = tan_v * double(view.width) / double(view.height);
    const double half_v = std::atan(tan_v), half_h = std::atan(tan_h);
    const double cos_v = std::cos(half_v), sin_v = std::sin(half_v);
    const double cos_h = std::cos(half_h), sin_h = std::sin(half_h);

    // A sphere at offset p from the target, seen from target - forward * D,
    // lies at depth D + p.forward; it is inside the side plane of half-angle h
    // when depth * sin h >= |p.across| * cos h + radius. The smallest D that
    // meets every plane of every framed sphere.
    double distance = 0;
    bool first = true;
    for (std::size_t i : counted) {
        const Sphere& s = spheres[i];
        if (!kept(s)) continue;
        const Vec3 p{s.center[0] - f.target[0], s.center[1] - f.target[1], s.center[2] - f.target[2]};
        const double along = dot(p, forward);
        const double across = std::fabs(dot(p, right)), upward = std::fabs(dot(p, up));
        const double need = std::max((across * cos_h + s.radius) / sin_h, (upward * cos_v + s.radius) / sin_v) - along;
        distance = first ? need : std::max(distance, need);
        first = false;
    }
    f.distance = distance;
    for (int c = 0; c < 3; ++c) f.position[c] = f.target[c] + back[c] * distance;
    return f;
}

}  // namespace orb
