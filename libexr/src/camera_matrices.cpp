#include "orb/exr/camera_matrices.h"

#include "orb/scene/camera_frame.h"

namespace orb::exr {
namespace {

using Matrix44d = std::array<std::array<double, 4>, 4>;

Matrix44d multiply(const Matrix44d& a, const Matrix44d& b) {
    Matrix44d r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

Matrix44 to_float(const Matrix44d& m) {
    Matrix44 r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[i][j] = static_cast<float>(m[i][j]);
    return r;
}

// The renderer's frame (orb/scene/camera_frame.h) as the axes of OpenEXR's camera space.
Matrix44d world_to_camera_d(const Camera& camera) {
    const CameraFrame f = camera_frame(camera);
    const Vec3 axes[3] = {f.right, f.up, f.forward};
    Matrix44d m{};
    for (int column = 0; column < 3; ++column) {
        for (int row = 0; row < 3; ++row) m[row][column] = axes[column][row];
        m[3][column] = -vec3::dot(camera.position, axes[column]);
    }
    m[3][3] = 1;
    return m;
}

}  // namespace

Matrix44 world_to_camera(const Camera& camera) { return to_float(world_to_camera_d(camera)); }

Matrix44 world_to_ndc(const Camera& camera, int width, int height) {
    const ViewExtents view = view_extents(camera, width, height);
    Matrix44d projection{};
    if (view.orthographic) {
        // Affine: camera (x, y, z) -> (X, Y, Z, 1) with X = 0.5 + 0.5 x/half_width
        // and Y = 0.5 - 0.5 y/half_height (y down); Z = z, the depth along the view.
        projection[0][0] = 0.5 / view.half_width;
        projection[1][1] = -0.5 / view.half_height;
        projection[2][2] = 1.0;
        projection[3][0] = 0.5;
        projection[3][1] = 0.5;
        projection[3][3] = 1.0;
    } else {
        // Camera (x, y, z) -> homogeneous (X, Y, Z, W) with W = z, so that
        // X/W = 0.5 + 0.5 x/(z tan_h) and Y/W = 0.5 - 0.5 y/(z tan_v) (y down),
        // the half extents being the tangents of the half-angles; Z/W = 1/z
        // keeps the matrix invertible.
        projection[0][0] = 0.5 / view.half_width;
        projection[1][1] = -0.5 / view.half_height;
        projection[2][0] = 0.5;
        projection[2][1] = 0.5;
        projection[2][3] = 1.0;
        projection[3][2] = 1.0;
    }
    return to_float(multiply(world_to_camera_d(camera), projection));
}

bool is_orthographic(const Matrix44& world_to_ndc) {
    // The W column: (0, 0, 0, 1) exactly for the affine matrix above; the
    // view direction (a unit vector) in the perspective one.
    return world_to_ndc[0][3] == 0 && world_to_ndc[1][3] == 0 && world_to_ndc[2][3] == 0 && world_to_ndc[3][3] == 1;
}

}  // namespace orb::exr
