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
// Perspective: projective, W = depth along the view. Orthographic
// (orthographic_height > 0): affine, the view's rectangle onto [0,1]², W = 1.
Matrix44 world_to_ndc(const Camera& camera, int width, int height);
// Whether a worldToNDC is an orthographic camera's (affine) rather than a perspective one's.
bool is_orthographic(const Matrix44& world_to_ndc);

}  // namespace orb::exr
