// glTF 2.0 import (.gltf with external or data-URI buffers, .glb): spheres,
// materials, camera, lights and node animation. Every rule is in docs/gltf.md.
#pragma once

#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "orb/import/image_decoder.h"
#include "orb/scene/scene.h"

namespace orb {

enum class NonSpherePolicy {
    Skip,   // leave meshes that are not spheres out, with one warning naming them
    Bound,  // replace each by its bounding sphere
    Error,  // refuse the file
};

// How KHR_lights_punctual intensities become Orb radiance (docs/gltf.md, "Lights").
enum class LightUnits {
    Photometric,  // candela and lux through 683 lm/W, as Blender's glTF importer does
    Radiometric,  // 1 cd taken as 1 W/sr and 1 lux as 1 W/m^2 (Orb before photometric units)
};

struct GltfImportOptions {
    bool strict = false;  // warnings that lose information become errors

    std::string scene;   // glTF scene index or name; empty: the default scene (or scene 0)
    std::string camera;  // glTF camera index, camera name or node name; empty: the first camera found
    std::string animation;  // glTF animation (clip) index or name; empty: the first clip

    // A mesh is a sphere when every vertex lies within this fraction of the
    // fitted radius from the fitted sphere.
    double sphere_tolerance = 1e-3;
    // Radius of POINTS without a _RADIUS attribute, in world units; <= 0:
    // 1% of the diagonal of the primitive's bounding box in world space.
    double point_radius = 0.0;
    NonSpherePolicy non_spheres = NonSpherePolicy::Skip;
    // Radius of the emissive sphere that stands for a punctual light, in world
    // units; <= 0: 1% of the diagonal of the scene's bounds.
    double light_radius = 0.0;
    // Directional lights become a distant large emitter (else: a warning).
    bool directional_lights = false;
    LightUnits light_units = LightUnits::Photometric;
    // An asset that brings no light at all (no punctual light imported, no
    // emissive material on a sphere) gets the default light, with a warning:
    // a neutral grey environment and a key light (docs/gltf.md).
    bool default_light = true;
    // Reads the base-colour, metallic-roughness and emissive textures into
    // each sphere's material (docs/gltf.md, "Textures"); without one,
    // textures are ignored with a warning.
    ImageDecoder image_decoder;
};

// The default light of an asset without any, as a glTF viewer lights one: a
// neutral grey environment of this uniform radiance (the background, dark
// grey), and a key light from the camera's upper left giving this irradiance
// at the centre of the spheres' box (an emissive sphere seen from there at
// sin(theta) = 1/4, radiance 16 E / pi, behind the camera's plane: out of
// view). The level is an exposure choice: the Khronos sample
// MetalRoughSpheresNoTextures then shows its spheres at a median luminance
// of 0.183 (256 x 256, 64 spp, its wholly covered pixels), mid-grey, as its
// reference screenshot does (0.183 there, over a background of 0.019); under
// the earlier uniform white environment of radiance 1 its background was
// display white and its white and metal rows vanished into it
// (docs/design/default-lighting.md).
inline constexpr double kDefaultEnvironmentRadiance = 0.05;
inline constexpr double kDefaultKeyIrradiance = 1.6 * std::numbers::pi;

struct GltfImportResult {
    Scene scene;
    std::vector<std::string> warnings;  // what the import left out or changed (fatal under --strict)
    std::vector<std::string> notices;   // what it added that the asset does not say (the default light); never fatal
    // Set when nothing in the asset became a sphere (the stand-ins of its
    // lights aside): what was left out and why, e.g. "1 mesh is not a sphere
    // (Suzanne)". import_scene refuses such a scene unless allowed.
    std::string no_spheres;
};

// `source` names the input in messages; external buffers are read only from
// inside `base_dir` (empty: they are refused). Throws InputError.
GltfImportResult import_gltf(std::string_view bytes, const std::string& source, const std::string& base_dir,
                             const GltfImportOptions& options);

}  // namespace orb
