// The canonical Orb scene: the in-memory model every tool shares.
// Conventions (docs/scene-format.md): right-handed, +y up, linear Rec.709
// colours, emission is radiance (W·sr⁻¹·m⁻²), lengths in scene units.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "orb/tables/material_kinds.h"
#include "orb/scene/animation.h"
#include "orb/scene/sphere_attributes.h"
#include "orb/scene/vec3.h"

namespace orb {

// How a material scatters light: one enumerator per row of ORB_MATERIAL_TABLE
// (libtables/include/orb/tables/material_kinds.h), with the table's values, so
// the scene model names the kernels' kinds without depending on the device's
// record layouts. librender converts it to the device's MaterialKind by value
// (checked row by row there).
#define ORB_SCENE_MATERIAL_TYPE(member, value, name, scn_word, prefix, caster_rule) member = value,
enum class MaterialType : int { ORB_MATERIAL_TABLE(ORB_SCENE_MATERIAL_TYPE) };
#undef ORB_SCENE_MATERIAL_TYPE

// Every material type, in the table's order.
inline constexpr MaterialType kMaterialTypes[] = {
#define ORB_SCENE_MATERIAL_TYPE(member, value, name, scn_word, prefix, caster_rule) MaterialType::member,
    ORB_MATERIAL_TABLE(ORB_SCENE_MATERIAL_TYPE)
#undef ORB_SCENE_MATERIAL_TYPE
};

// The type's name in the scene format ("diffuse", "dielectric", ...), the
// table's "scene name" column.
const char* material_type_name(MaterialType type);

struct Material {
    std::string name;
    MaterialType type = MaterialType::Diffuse;
    Vec3 color{0.0, 0.0, 0.0};     // reflectance / base colour / transmittance tint, each in [0,1]
    Vec3 emission{0.0, 0.0, 0.0};  // emitted radiance, >= 0
    double ior = 1.5;              // used by dielectrics only
    double roughness = 0.0;        // perceptual roughness in [0,1], dielectric and pbr only (0 for the others)
    double metallic = 0.0;         // in [0,1], pbr only (0 for the others)
    bool operator==(const Material&) const = default;
};

// Whether a material type reads `roughness` and `metallic`.
bool has_roughness(MaterialType type);
bool has_metallic(MaterialType type);

struct Sphere {
    std::string name;
    Vec3 center{0.0, 0.0, 0.0};
    double radius = 1.0;
    std::uint32_t material = 0;  // index into Scene::materials
    bool operator==(const Sphere&) const = default;
};

struct Camera {
    Vec3 position{0.0, 0.0, 1.0};
    Vec3 target{0.0, 0.0, 0.0};
    Vec3 up{0.0, 1.0, 0.0};
    double vfov_deg = 42.87978100351012;  // vertical field of view of the whole image; SmallptGPU's 2*atan(pi/8)
    double aperture = 0.0;      // lens diameter; 0 is a pinhole
    double focus_distance = 1.0;
    // Greater than zero: an orthographic camera whose view is this many scene
    // units high (parallel rays along the view direction; vfov_deg and the lens
    // do not apply). Zero: the perspective camera above.
    double orthographic_height = 0.0;
    bool operator==(const Camera&) const = default;
};

struct RenderSettings {
    int width = 640;
    int height = 480;
    int spp = 64;
    int max_depth = 6;
    bool operator==(const RenderSettings&) const = default;
};

// An environment map's texels: linear Rec.709 radiance, before the
// environment's intensity. Row-major, row 0 the top row (+y, the zenith),
// three floats per texel. Plain numbers, no file format: libexr reads them
// from an EXR (orb/exr/environment_map.h), librender samples them.
struct EnvironmentImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // width * height * 3
    bool operator==(const EnvironmentImage&) const = default;
};

// Light arriving from infinitely far away in every direction a ray escapes
// to (docs/scene-format.md, "Environment"; docs/rendering.md).
enum class EnvironmentKind {
    None,   // rays that leave the scene carry no radiance
    Color,  // the same radiance from every direction
    Map,    // an equirectangular (latitude-longitude) HDR image
};

struct Environment {
    EnvironmentKind kind = EnvironmentKind::None;
    Vec3 color{0.0, 0.0, 0.0};  // Color: radiance, each >= 0
    std::string map;            // Map: the image's path as the scene writes it (relative: to the scene's folder)
    double intensity = 1.0;     // Map: radiance = intensity * texel
    double rotation_deg = 0.0;  // Map: turn about +y, right-handed (docs/scene-format.md)
    // Map: the texels, once a loader has read `map` (orb::exr::load_environment_map).
    // Not part of the JSON form; compared by content, and part of the content hash.
    std::shared_ptr<const EnvironmentImage> image;
    bool operator==(const Environment& other) const;
};

struct Scene {
    Camera camera;
    RenderSettings render;
    std::vector<Material> materials;
    std::vector<Sphere> spheres;
    Animation animation;  // empty for static scenes
    Environment environment;  // kind None for scenes without one
    // Per-sphere colours and properties, index for index with `spheres`
    // (orb/scene/sphere_attributes.h); empty for most scenes.
    SphereAttributes sphere_attributes;
    bool operator==(const Scene&) const = default;
};

// Whether the environment gives any light: a colour that is not black, or a
// map whose intensity is positive (and whose texels, once loaded, are not all 0).
bool environment_emits(const Environment& environment);

// Whether anything in the scene emits light: a sphere whose material has
// emission, or an environment that is not black (a map counts unless its
// intensity is 0 or its attached texels are all 0). A scene without light
// renders black.
bool scene_has_light(const Scene& scene);

// The vertical field of view SmallptGPU frames with: its image plane at unit
// distance is pi/4 high, so vfov = 2*atan(pi/8).
double smallptgpu_vfov_deg();

}  // namespace orb
