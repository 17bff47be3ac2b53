// The scene around a cloud of spheres (orb/import/point_cloud.h). The
// numbers here are documented in docs/orb-import.md ("PLY point clouds");
// change them together.
#include "orb/import/point_cloud.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "default_lights.h"
#include "orb/scene/auto_framing.h"
#include "orb/scene/detail/json_text.h"
#include "orb/scene/error.h"
#include "srgb.h"

namespace orb {
namespace {

struct Bounds {
    Vec3 lo{}, hi{};
    double diagonal() const { return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]); }
};

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

Scene point_cloud_scene(PointCloud cloud, double point_radius, const std::string& source) {
    Scene scene;
    const std::size_t count = cloud.spheres.size();
    // One material for every point; the points' colours, when given, are the
    // spheres' own (Scene::sphere_attributes), not a material per colour: a
    // million colours read, hash and upload as arrays.
    Material point;
    point.name = "point";
    point.color = {0.8, 0.8, 0.8};  // the scene format's default colour
    scene.materials.push_back(point);
    scene.spheres = std::move(cloud.spheres);
    for (Sphere& sphere : scene.spheres) sphere.material = 0;
    SphereAttributes& attributes = scene.sphere_attributes;
    attributes.colors = std::move(cloud.colors);
    attributes.properties = std::move(cloud.properties);

    // The lights go around the framed points: stray points would push them far away.
    const double framed_radius = frame_cloud(scene, point_radius, source);
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

double linear_from_display(double encoded) { return detail::srgb_to_linear(encoded); }

}  // namespace orb
