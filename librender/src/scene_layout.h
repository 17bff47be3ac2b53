// The scene and camera as device records (libtables/include/orb/tables/device_types.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "orb/tables/device_types.h"
#include "orb/scene/scene.h"
#include "sphere_bvh.h"

namespace orb::render {

// One vector per scene table of render_pass, generated from the kernel's
// argument list so that a new table appears here without an edit.
struct SceneTables {
#define ORB_SCENE_TABLES_FILM(...)
#define ORB_SCENE_TABLES_TABLE(type, name) std::vector<device::type> name;
#define ORB_SCENE_TABLES_PARAMS(type, name)
    ORB_RENDER_PASS_ARGUMENTS(ORB_SCENE_TABLES_FILM, ORB_SCENE_TABLES_TABLE, ORB_SCENE_TABLES_PARAMS)
#undef ORB_SCENE_TABLES_FILM
#undef ORB_SCENE_TABLES_TABLE
#undef ORB_SCENE_TABLES_PARAMS
};

struct SceneLayout {
    SceneTables tables;
    device::SceneCounts counts{};
    device::EnvironmentParams environment{};  // width 0: none
    bool uniform_lights = true;  // every light has the same picking probability (so uniform picking is exact)
    // What the program needs code for (kernels/bsdf.cl, ORB_MATERIAL_KINDS):
    // bit k set when a sphere's material is MaterialKind k; whether a glass
    // is rough (ORB_ROUGH_DIELECTRIC). Code a scene does not use still costs
    // GPU registers, so its program leaves that code out.
    std::uint32_t material_kinds = 0;
    bool rough_dielectric = false;
    // The spheres carry their own colours (Scene::sphere_attributes.colors,
    // in SphereRecord::color): the program reads those (ORB_SPHERE_COLORS).
    bool sphere_colors = false;
};

// A linear colour, each component in [0, 1], as SphereRecord::color holds it
// (device_types.h: the square roots, rounded to 11, 11 and 10 bits).
std::uint32_t pack_sphere_color(float red, float green, float blue);

// The device tables in BVH order: the spheres outside the tree first (every
// ray tests them), then one packet per BVH leaf. A scene too small for a tree
// (and every scene with use_bvh false) keeps the scene's own order, all
// spheres outside. SphereRecord::scene_index maps back for the id pass.
//
// The environment (environment_layout.h) is one more light: next-event
// estimation picks it with probability kEnvironmentLightShare when spheres
// emit too (else 1), and the emissive spheres share the rest by power.
//
// Throws std::runtime_error naming the sphere for input the kernels cannot
// render (a material index out of range, a non-positive or non-finite radius),
// std::invalid_argument for an environment map whose texels are not loaded.
SceneLayout layout_scene(const Scene& scene, bool use_bvh = true);

// The same in two steps: the tree layout_scene builds for the scene (empty
// when it is too small for one, or use_bvh is false; the same checks and
// errors), and the layout with a given tree over the scene's spheres -- one
// scene_bvh built, or a tree refitted to them (refit_sphere_bvh).
SphereBvh scene_bvh(const Scene& scene, bool use_bvh = true);
SceneLayout layout_scene(const Scene& scene, const SphereBvh& bvh);

// The environment's share of the light picks when spheres emit too. Its
// power relative to the spheres' would need a scene radius, which the
// radius-1e4 walls and floors of sphere scenes make meaningless (pbrt-v4
// weighs infinite lights by the scene's bounding sphere); a fixed half
// costs at most a factor 2 in the variance of either kind of light.
inline constexpr double kEnvironmentLightShare = 0.5;

// Casters (kernels/caustic_casters.cl) are listed when a scene has at most
// this many; past it none are. Every vertex with a density tests every
// caster's cone, and a cloud of glass beads gains little from aiming at each.
inline constexpr std::size_t kMaxCausticCasters = 8;

// The camera as the kernels read it (orb/scene/camera_frame.h). Throws
// std::runtime_error for a camera without a direction, std::invalid_argument
// for an image size that is not positive.
device::CameraParams layout_camera(const Camera& camera, int width, int height);

}  // namespace orb::render
