// OpenEXR's standard worldToCamera / worldToNDC attributes for an Orb camera.
// Imath multiplies row vectors (p' = p * M). Camera space is OpenEXR's
// (RenderMan's): left-handed, +x right, +y up, +z along the view direction.
// NDC: (0,0) is the top-left corner of the display window, (1,1) the
// bottom-right; a world point maps there by p * worldToNDC with the
// homogeneous divide (Imath's multVecMatrix), ignoring z.
#pragma once

#include <array>

#include "orb/scene/scene.h"

namespace orb::exr {

using Matrix44 = std::array<std::array<float, 4>, 4>;  // [row][column], Imath layout

Matrix44 world_to_camera(const Camera& camera);
Matrix44 world_to_ndc(const Camera& camera, int width, int height);

}  // namespace orb::exr
