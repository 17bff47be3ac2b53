// The canonical Orb scene: the in-memory model every tool shares.
// Conventions (docs/scene-format.md): right-handed, +y up, linear Rec.709
// colours, emission is radiance (W·sr⁻¹·m⁻²), lengths in scene units.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "orb/kernels/device_types.h"
#include "orb/scene/animation.h"

namespace orb {

using Vec3 = std::array<double, 3>;

// Diffuse, Mirror, Dielectric, Pbr: the kinds the kernels implement, defined
// once for the host and the kernels in kernels/include/orb/kernels/device_types.h.
using MaterialType = device::MaterialKind;

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
    bool operator==(const Camera&) const = default;
};

struct RenderSettings {
    int width = 640;
    int height = 480;
    int spp = 64;
    int max_depth = 6;
    bool operator==(const RenderSettings&) const = default;
};

struct Scene {
    Camera camera;
    RenderSettings render;
    std::vector<Material> materials;
    std::vector<Sphere> spheres;
    Animation animation;  // empty for static scenes
    bool operator==(const Scene&) const = default;
};

// The vertical field of view SmallptGPU frames with: its image plane at unit
// distance is pi/4 high, so vfov = 2*atan(pi/8).
double smallptgpu_vfov_deg();

}  // namespace orb
