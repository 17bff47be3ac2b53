// An asset with no light at all would render black (many sample assets
// rely on the viewer's lighting): it gets what a glTF viewer gives it, a
// neutral grey environment and a key light, at the level orb/import/gltf.h
// explains (docs/gltf.md, "Default light").
#include <algorithm>
#include <limits>

#include "gltf_internal.h"
#include "orb/scene/detail/json_text.h"
#include "orb/scene/camera_frame.h"

namespace orb::gltf {
namespace {

// The key light: from the camera's upper left and from behind it, as a
// photographer's key light stands (the direction orb-import's default key
// light has for a cloud seen from +z), aimed at the centre of the spheres'
// box. Its distance s and radius s/4 give it the same solid angle, so the
// same irradiance at the centre, wherever it stands: at least 4R (R, half the
// box's diagonal), and far enough that the whole sphere lies behind the
// camera's plane, where no camera ray (perspective or orthographic) starts or
// goes: it lights the view without being in it, whatever camera the asset has.
void add_key_light(Scene& scene) {
    using namespace vec3;
    Vec3 low, high;
    low.fill(std::numeric_limits<double>::infinity());
    high.fill(-std::numeric_limits<double>::infinity());
    for (const Sphere& sphere : scene.spheres)
        for (int c = 0; c < 3; ++c) {
            low[c] = std::min(low[c], sphere.center[c] - sphere.radius);
            high[c] = std::max(high[c], sphere.center[c] + sphere.radius);
        }
    const Vec3 center = scaled(add(low, high), 0.5);
    const double box_radius = length(sub(high, low)) / 2;
    const CameraFrame frame = camera_frame(scene.camera);
    const Vec3 direction = normalized(add(add(scaled(frame.right, -1), scaled(frame.up, 2)), scaled(frame.forward, -1)));
    // Depth along the view of a point at distance s: depth(centre) + s (direction . forward); the sphere is
    // behind the camera's plane when that is below -s/4, with a margin of a tenth of R.
    const double centre_depth = dot(sub(center, scene.camera.position), frame.forward);
    const double receding = -dot(direction, frame.forward) - 0.25;  // > 0: 1/sqrt(6) - 1/4
    const double distance = std::max(4 * box_radius, (centre_depth + 0.1 * box_radius) / receding);
    Material key;
    key.name = "default key light";
    key.color = {0, 0, 0};
    // A sphere of radiance L seen at sin(theta) = 1/4 gives the irradiance E = pi L / 16.
    const double radiance = 16 * kDefaultKeyIrradiance / std::numbers::pi;
    key.emission = {radiance, radiance, radiance};
    scene.materials.push_back(key);
    Sphere light;
    light.name = "default key light";
    light.center = add(center, scaled(direction, distance));
    light.radius = distance / 4;
    light.material = static_cast<std::uint32_t>(scene.materials.size() - 1);
    scene.spheres.push_back(light);
    // Its entries of the per-sphere arrays (a point cloud's COLOR_0): its material's black, no value.
    SphereAttributes& attributes = scene.sphere_attributes;
    if (!attributes.colors.empty()) attributes.colors.insert(attributes.colors.end(), 3, 0.0f);
    for (SphereProperty& property : attributes.properties) property.values.push_back(kNoValue);
}

}  // namespace

void add_default_light(Scene& scene, const std::string& source, std::vector<std::string>& notices) {
    if (scene_has_light(scene)) return;
    const double l = kDefaultEnvironmentRadiance;
    scene.environment = Environment{};
    scene.environment.kind = EnvironmentKind::Color;
    scene.environment.color = {l, l, l};
    // Without spheres (--allow-empty) there is nothing to aim a key light at.
    if (!scene.spheres.empty()) add_key_light(scene);
    notices.push_back(source +
                      ": the asset has no light (no KHR_lights_punctual light imported, no emissive material); added "
                      "a grey environment of radiance " + detail::format_number(l) +
                      (scene.spheres.empty() ? std::string() : " and a key light from the camera's upper left") +
                      " (--no-default-light leaves the scene unlit)");
}

}  // namespace orb::gltf
