// The scene and camera in the form the kernels read (kernels/scene.cl and
// kernels/camera.cl describe the same layout from the device side).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "orb/scene/scene.h"

namespace orb::render {

using Float4 = std::array<float, 4>;  // matches cl_float4's size and layout

enum class KernelMaterial : int { Diffuse = 0, Mirror = 1, Dielectric = 2 };

struct SceneLayout {
    std::vector<Float4> packets;        // 4 per group of four spheres: centre x, y, z, radius^2
    std::vector<Float4> records;        // 3 per sphere: centre+radius, colour+type, emission+ior
    std::vector<std::int32_t> lights;   // indices of emissive spheres
    int packet_count = 0;
    int sphere_count = 0;

    std::size_t bytes() const;
};

// Throws std::runtime_error naming the sphere for input the kernels cannot
// render (a material index out of range, a non-positive or non-finite radius).
SceneLayout layout_scene(const Scene& scene);

struct CameraLayout {
    Float4 origin{};
    Float4 right{};    // unit
    Float4 up{};       // unit
    Float4 forward{};  // unit
    Float4 lens{};     // half width and half height of the image plane at unit distance, lens radius, focus distance
};

// Throws std::runtime_error for a camera without a direction.
CameraLayout layout_camera(const Camera& camera, int width, int height);

}  // namespace orb::render
