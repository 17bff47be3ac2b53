// Splitting a mesh's triangles into connected parts, so that one mesh holding
// several spheres gives one sphere each, and telling closed surfaces from open
// ones (docs/gltf.md, "Sphere detection").
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

#include "gltf_internal.h"

namespace orb::gltf {
namespace {

// Vertices closer than this fraction of the mesh's bounding-box extent are
// one vertex: exporters split vertices along UV seams and between
// primitives, with equal (or float-rounded) positions.
constexpr double kWeldFraction = 1e-6;

class UnionFind {
public:
    explicit UnionFind(std::size_t size) : parent_(size) { std::iota(parent_.begin(), parent_.end(), 0u); }
    std::uint32_t find(std::uint32_t i) {
        while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
        return i;
    }
    void join(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
    }

private:
    std::vector<std::uint32_t> parent_;
};

// For each point, a representative of the points within `epsilon` of it
// (chains of close points share one). Points are hashed into cells of size
// 2 epsilon measured from `lo`, so each has its neighbours in the 27 cells
// around its own: linear time, whatever the shape.
std::vector<std::uint32_t> weld(const std::vector<AnimVec3>& points, const AnimVec3& lo, double epsilon) {
    std::vector<std::uint32_t> representative(points.size());
    std::iota(representative.begin(), representative.end(), 0u);
    const bool finite = std::all_of(points.begin(), points.end(), [](const AnimVec3& p) {
        return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
    });
    if (!finite || !std::isfinite(epsilon)) return representative;  // nothing sensible to weld
    const double cell = epsilon > 0 ? 2 * epsilon : 1.0;
    using Key = std::array<long long, 3>;
    auto key_of = [&](const AnimVec3& p) {
        return Key{(long long)std::floor((p[0] - lo[0]) / cell), (long long)std::floor((p[1] - lo[1]) / cell),
                   (long long)std::floor((p[2] - lo[2]) / cell)};
    };
    std::map<Key, std::vector<std::uint32_t>> cells;
    UnionFind same(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        const Key key = key_of(points[i]);
        bool joined = false;
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy)
                for (long long dz = -1; dz <= 1; ++dz) {
                    auto it = cells.find(Key{key[0] + dx, key[1] + dy, key[2] + dz});
                    if (it == cells.end()) continue;
                    for (std::uint32_t j : it->second)
                        if (std::fabs(points[i][0] - points[j][0]) <= epsilon &&
                            std::fabs(points[i][1] - points[j][1]) <= epsilon &&
                            std::fabs(points[i][2] - points[j][2]) <= epsilon)
                        {
                            same.join(i, j);
                            joined = true;
                        }
                }
        // A point already welded is represented by its partner: duplicates
        // never pile up in one cell.
        if (!joined) cells[key].push_back(i);
    }
    for (std::uint32_t i = 0; i < points.size(); ++i) representative[i] = same.find(i);
    return representative;
}

}  // namespace

std::vector<SurfacePart> connected_parts(const std::vector<AnimVec3>& points,
                                         const std::vector<std::array<std::uint32_t, 3>>& triangles) {
    double extent = 0.0;
    AnimVec3 lo{};
    if (!points.empty()) {
        lo = points[0];
        AnimVec3 hi = points[0];
        for (const AnimVec3& p : points)
            for (int c = 0; c < 3; ++c) {
                lo[c] = std::min(lo[c], p[c]);
                hi[c] = std::max(hi[c], p[c]);
            }
        for (int c = 0; c < 3; ++c) extent = std::max(extent, hi[c] - lo[c]);
    }
    const std::vector<std::uint32_t> welded = weld(points, lo, std::isfinite(extent) ? kWeldFraction * extent : 0.0);
    UnionFind connected(points.size());
    for (const auto& t : triangles) {
        connected.join(welded[t[0]], welded[t[1]]);
        connected.join(welded[t[0]], welded[t[2]]);
    }
    // Parts in the order of their first triangle; vertices renumbered per part.
    std::map<std::uint32_t, std::size_t> part_of_root;
    std::vector<SurfacePart> parts;
    std::vector<std::map<std::uint32_t, std::uint32_t>> local_index;
    for (const auto& t : triangles) {
        const std::uint32_t root = connected.find(welded[t[0]]);
        auto [it, added] = part_of_root.emplace(root, parts.size());
        if (added) {
            parts.emplace_back();
            local_index.emplace_back();
        }
        SurfacePart& part = parts[it->second];
        std::array<std::uint32_t, 3> local{};
        for (int k = 0; k < 3; ++k) {
            auto [slot, fresh] = local_index[it->second].emplace(welded[t[k]], std::uint32_t(part.points.size()));
            if (fresh) part.points.push_back(points[welded[t[k]]]);
            local[k] = slot->second;
        }
        part.triangles.push_back(local);
    }
    // Every original vertex belongs to the part of its welded vertex.
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        auto it = part_of_root.find(connected.find(welded[i]));
        if (it != part_of_root.end() && local_index[it->second].count(welded[i]))
            parts[it->second].source_vertices.push_back(i);
    }
    return parts;
}

bool is_closed(const std::vector<std::array<std::uint32_t, 3>>& triangles) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const auto& t : triangles) {
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;  // collapsed by welding
        for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
    }
    if (uses.empty()) return false;
    return std::all_of(uses.begin(), uses.end(), [](const auto& edge) { return edge.second == 2; });
}

double solid_angle_seen_from(const AnimVec3& center, const std::vector<AnimVec3>& points,
                             const std::vector<std::array<std::uint32_t, 3>>& triangles) {
    double total = 0.0;
    for (const auto& t : triangles) {
        AnimVec3 v[3];
        double length[3];
        for (int k = 0; k < 3; ++k) {
            for (int c = 0; c < 3; ++c) v[k][c] = points[t[k]][c] - center[c];
            length[k] = detail::length3(v[k]);
        }
        // Van Oosterom and Strackee: tan(omega / 2) = det / denominator.
        const AnimVec3 cross{v[1][1] * v[2][2] - v[1][2] * v[2][1], v[1][2] * v[2][0] - v[1][0] * v[2][2],
                             v[1][0] * v[2][1] - v[1][1] * v[2][0]};
        const double det = detail::dot3(v[0], cross);
        const double denominator = length[0] * length[1] * length[2] + detail::dot3(v[0], v[1]) * length[2] +
                                   detail::dot3(v[0], v[2]) * length[1] + detail::dot3(v[1], v[2]) * length[0];
        total += std::fabs(2.0 * std::atan2(det, denominator));
    }
    return total;
}

}  // namespace orb::gltf
