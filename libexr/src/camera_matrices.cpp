#include "orb/exr/camera_matrices.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace orb::exr {
namespace {

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 normalized(const Vec3& v) {
    const double length = std::sqrt(dot(v, v));
    if (!(length > 0)) throw std::invalid_argument("degenerate camera frame");
    return {v[0] / length, v[1] / length, v[2] / length};
}

struct Frame {
    Vec3 right, up, forward;
};

// The same orthonormal frame the renderer's camera uses: forward toward the
// target, right = forward x up, up recomputed to be orthogonal; an up
// parallel to the view falls back to the world axis least aligned with it.
Frame camera_frame(const Camera& camera) {
    Frame f;
    f.forward = normalized(sub(camera.target, camera.position));
    Vec3 right = cross(f.forward, camera.up);
    if (std::sqrt(dot(right, right)) < 1e-9 * std::max(1.0, std::sqrt(dot(camera.up, camera.up)))) {
        int least = 0;
        for (int axis = 1; axis < 3; ++axis)
            if (std::fabs(f.forward[axis]) < std::fabs(f.forward[least])) least = axis;
        Vec3 world_axis{0, 0, 0};
        world_axis[least] = 1;
        right = cross(f.forward, world_axis);
    }
    f.right = normalized(right);
    f.up = cross(f.right, f.forward);
    return f;
}

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

Matrix44d world_to_camera_d(const Camera& camera) {
    const Frame f = camera_frame(camera);
    const Vec3 axes[3] = {f.right, f.up, f.forward};
    Matrix44d m{};
    for (int column = 0; column < 3; ++column) {
        for (int row = 0; row < 3; ++row) m[row][column] = axes[column][row];
        m[3][column] = -dot(camera.position, axes[column]);
    }
    m[3][3] = 1;
    return m;
}

}  // namespace

Matrix44 world_to_camera(const Camera& camera) { return to_float(world_to_camera_d(camera)); }

Matrix44 world_to_ndc(const Camera& camera, int width, int height) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("image size must be positive");
    if (camera.orthographic_height > 0) {
        const double half_v = camera.orthographic_height / 2;
        const double half_h = half_v * width / height;
        // Affine: camera (x, y, z) -> (X, Y, Z, 1) with X = 0.5 + 0.5 x/half_h
        // and Y = 0.5 - 0.5 y/half_v (y down); Z = z, the depth along the view.
        Matrix44d projection{};
        projection[0][0] = 0.5 / half_h;
        projection[1][1] = -0.5 / half_v;
        projection[2][2] = 1.0;
        projection[3][0] = 0.5;
        projection[3][1] = 0.5;
        projection[3][3] = 1.0;
        return to_float(multiply(world_to_camera_d(camera), projection));
    }
    constexpr double kPi = 3.14159265358979323846;
    const double tan_half_v = std::tan(camera.vfov_deg * kPi / 360.0);
    const double tan_half_h = tan_half_v * width / height;
    // Camera (x, y, z) -> homogeneous (X, Y, Z, W) with W = z, so that
    // X/W = 0.5 + 0.5 x/(z tan_h) and Y/W = 0.5 - 0.5 y/(z tan_v) (y down);
    // Z/W = 1/z keeps the matrix invertible.
    Matrix44d projection{};
    projection[0][0] = 0.5 / tan_half_h;
    projection[1][1] = -0.5 / tan_half_v;
    projection[2][0] = 0.5;
    projection[2][1] = 0.5;
    projection[2][3] = 1.0;
    projection[3][2] = 1.0;
    return to_float(multiply(world_to_camera_d(camera), projection));
}

bool is_orthographic(const Matrix44& world_to_ndc) {
    // The W column: (0, 0, 0, 1) exactly for the affine matrix above; the
    // view direction (a unit vector) in the perspective one.
    return world_to_ndc[0][3] == 0 && world_to_ndc[1][3] == 0 && world_to_ndc[2][3] == 0 && world_to_ndc[3][3] == 1;
}

}  // namespace orb::exr
