// The scene around a point cloud. The numbers here are documented in
// docs/orb-import.md ("PLY point clouds"); change them together.
#include "ply_scene.h"

#include "default_lights.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

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

// Looks at the cloud from above the +z side (30 degrees up), framed by the
// rule every importer shares (orb/scene/auto_framing.h: stray points left
// out, the framed points filling the tighter image direction but for a 10%
// margin). Returns the radius of the framed points' bounds (half their box's
// diagonal, at least `point_radius` so that a lone point counts), around the
// camera's target, which places the default lights.
double frame_cloud(Scene& scene, double point_radius, const std::string& source) {
    constexpr double kElevation = 30.0 * std::numbers::pi / 180.0;
    const FramingView view{{0.0, std::sin(kElevation), std::cos(kElevation)}, {0, 1, 0}, scene.camera.vfov_deg,
                           scene.render.width, scene.render.height};
    const Framing framing = *frame_spheres(scene.spheres, view);  // a cloud has at least one point
    const Vec3& center = framing.target;
    const double distance = framing.distance;
    const Bounds framed{framing.lo, framing.hi};
    const double radius = std::max(framed.diagonal() / 2, point_radius);
    scene.camera.position = framing.position;
    // Far from the origin relative to its size, the offset vanishes in rounding.
    const Vec3& p = scene.camera.position;
    if (std::hypot(p[0] - center[0], p[1] - center[1], p[2] - center[2]) < 0.5 * distance)
        throw InputError(source + ": the cloud lies too far from the origin for its size (radius " +
                         detail::format_number(radius) + " around " + detail::format_number(center[0]) + ", " +
                         detail::format_number(center[1]) + ", " + detail::format_number(center[2]) +
                         "): no camera can be placed in double precision; move it or pass a larger --radius");
    scene.camera.target = center;
    scene.camera.up = {0, 1, 0};
    scene.camera.focus_distance = distance;
    return radius;
}

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
    Scene scene;
    const double radius = options.radius > 0 ? options.radius : default_point_radius(columns.centers);
    const std::size_t count = columns.centers.size();

    // One material for every point; the points' colours, when the file has
    // them, are the spheres' own (Scene::sphere_attributes), not a material
    // per colour: a million colours read, hash and upload as arrays.
    Material point;
    point.name = "point";
    point.color = {0.8, 0.8, 0.8};  // the scene format's default colour
    scene.materials.push_back(point);
    scene.spheres.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        Sphere& sphere = scene.spheres[i];
        sphere.center = columns.centers[i];
        sphere.radius = columns.radii.empty() ? radius : columns.radii[i];
    }
    SphereAttributes& attributes = scene.sphere_attributes;
    if (!columns.colors.empty()) {
        // 256 levels per 8-bit channel: decode each level once.
        std::unordered_map<double, float> linear_of;
        auto linear = [&linear_of](double encoded) {
            auto [found, inserted] = linear_of.try_emplace(encoded, 0.0f);
            if (inserted) found->second = static_cast<float>(srgb_to_linear(encoded));
            return found->second;
        };
        attributes.colors.resize(3 * count);
        for (std::size_t i = 0; i < count; ++i)
            for (int c = 0; c < 3; ++c) attributes.colors[3 * i + c] = linear(columns.colors[i][c]);
    }
    attributes.properties = std::move(columns.properties);
    columns = {};  // the sphere list is the only copy from here on

    // The lights go around the framed points: stray points would push them far away.
    const double framed_radius = frame_cloud(scene, radius, source);
    detail::add_default_lights(scene, scene.camera.target, framed_radius);
    // The lights' entries of the arrays: their material's colour (black), and
    // 0 for every property (styling leaves emissive spheres alone).
    for (std::size_t i = count; i < scene.spheres.size(); ++i) {
        if (!attributes.colors.empty())
            for (int c = 0; c < 3; ++c)
                attributes.colors.push_back(static_cast<float>(scene.materials[scene.spheres[i].material].color[c]));
        for (SphereProperty& property : attributes.properties) property.values.push_back(0.0f);
    }
    return scene;
}

}  // namespace orb::ply
