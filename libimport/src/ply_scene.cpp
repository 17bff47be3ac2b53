// The scene around a point cloud. The numbers here are documented in
// docs/orb-import.md ("PLY point clouds"); change them together.
#include "ply_scene.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "orb/import/point_cloud.h"
#include "orb/scene/detail/json_text.h"
#include "srgb.h"
#include "orb/scene/auto_framing.h"
#include "orb/scene/error.h"

namespace orb::ply {
namespace {

struct Bounds {
    Vec3 lo{}, hi{};
    double diagonal() const { return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]); }
};

// PLY colours are display values (what point-cloud viewers show as is), so
// they are sRGB-encoded; the scene holds linear Rec.709 reflectance.
using detail::srgb_to_linear;

}  // namespace

std::vector<std::string> keep_usable_properties(std::vector<SphereProperty>& properties, const std::string& source) {
    std::vector<std::string> warnings;
    std::vector<SphereProperty> kept;
    for (SphereProperty& property : properties) {
        std::size_t bad = property.values.size();
        for (std::size_t i = 0; i < property.values.size() && bad == property.values.size(); ++i)
            if (!std::isfinite(property.values[i])) bad = i;
        if (bad < property.values.size())
            warnings.push_back(source + ": ignored vertex property '" + property.name + "': vertex " +
                               std::to_string(bad) + " holds " + detail::format_number(property.values[bad]) +
                               " (a sphere property must be a finite 32-bit float)");
        else
            kept.push_back(std::move(property));
    }
    properties = std::move(kept);
    return warnings;
}

double default_point_radius(const std::vector<Vec3>& centers) {
    if (centers.empty()) return 1.0;
    // The spacing of the cloud without its stray points (the framing's rule,
    // orb/scene/auto_framing.h): a few far points would make every point huge.
    const StrayBounds strays = stray_bounds(centers);
    Bounds b;
    std::size_t kept = 0;
    for (const Vec3& p : centers) {
        if (!strays.keeps(p)) continue;
        for (int c = 0; c < 3; ++c) {
            b.lo[c] = kept == 0 ? p[c] : std::min(b.lo[c], p[c]);
            b.hi[c] = kept == 0 ? p[c] : std::max(b.hi[c], p[c]);
        }
        ++kept;
    }
    const double diagonal = b.diagonal();
    if (!(diagonal > 0) || !std::isfinite(diagonal)) return 1.0;
    const double spacing = diagonal / (std::sqrt(3.0) * std::cbrt(static_cast<double>(kept)));
    return spacing / 2;
}

Scene cloud_scene(VertexColumns columns, const PlyImportOptions& options, const std::string& source) {
    const double radius = options.radius > 0 ? options.radius : default_point_radius(columns.centers);
    const std::size_t count = columns.centers.size();
    PointCloud cloud;
    cloud.spheres.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        Sphere& sphere = cloud.spheres[i];
        sphere.center = columns.centers[i];
        sphere.radius = columns.radii.empty() ? radius : columns.radii[i];
    }
    if (!columns.colors.empty()) {
        // 256 levels per 8-bit channel: decode each level once.
        std::unordered_map<double, float> linear_of;
        auto linear = [&linear_of](double encoded) {
            auto [found, inserted] = linear_of.try_emplace(encoded, 0.0f);
            if (inserted) found->second = static_cast<float>(srgb_to_linear(encoded));
            return found->second;
        };
        cloud.colors.resize(3 * count);
        for (std::size_t i = 0; i < count; ++i)
            for (int c = 0; c < 3; ++c) cloud.colors[3 * i + c] = linear(columns.colors[i][c]);
    }
    cloud.properties = std::move(columns.properties);
    columns = {};  // the sphere list is the only copy from here on
    return point_cloud_scene(std::move(cloud), radius, source);
}

}  // namespace orb::ply
