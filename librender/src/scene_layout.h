// The scene and camera as device records (kernels/include/orb/kernels/device_types.h).
#pragma once

#include <cstddef>
#include <vector>

#include "orb/kernels/device_types.h"
#include "orb/scene/scene.h"

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
    bool uniform_lights = true;  // every light has the same picking probability (so uniform picking is exact)
};

// The device tables in BVH order: the spheres outside the tree first (every
// ray tests them), then one packet per BVH leaf. A scene too small for a tree
// (and every scene with use_bvh false) keeps the scene's own order, all
// spheres outside. SphereRecord::scene_index maps back for the id pass.
//
// Throws std::runtime_error naming the sphere for input the kernels cannot
// render (a material index out of range, a non-positive or non-finite radius).
SceneLayout layout_scene(const Scene& scene, bool use_bvh = true);

// Throws std::runtime_error for a camera without a direction.
device::CameraParams layout_camera(const Camera& camera, int width, int height);

}  // namespace orb::render
