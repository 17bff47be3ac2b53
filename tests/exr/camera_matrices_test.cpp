#include <gtest/gtest.h>

#include <cmath>

#include "orb/exr/camera_matrices.h"

using namespace orb::exr;

namespace {

// Row vector times matrix with the homogeneous divide, as Imath's multVecMatrix.
std::array<double, 3> transform(const Matrix44& m, std::array<double, 3> p) {
    double out[4];
    for (int j = 0; j < 4; ++j) out[j] = p[0] * m[0][j] + p[1] * m[1][j] + p[2] * m[2][j] + m[3][j];
    return {out[0] / out[3], out[1] / out[3], out[2] / out[3]};
}

orb::Camera looking_down_minus_z() {
    orb::Camera camera;
    camera.position = {1, 2, 3};
    camera.target = {1, 2, -7};
    camera.up = {0, 1, 0};
    camera.vfov_deg = 60;
    return camera;
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace

TEST(CameraMatrices, WorldToCameraIsLeftHandedWithZForward) {
    const orb::Camera camera = looking_down_minus_z();
    const Matrix44 m = world_to_camera(camera);
    auto at_origin = transform(m, {1, 2, 3});
    EXPECT_NEAR(at_origin[0], 0, 1e-6);
    EXPECT_NEAR(at_origin[1], 0, 1e-6);
    EXPECT_NEAR(at_origin[2], 0, 1e-6);
    auto ahead = transform(m, {1, 2, -2});  // 5 units in front
    EXPECT_NEAR(ahead[2], 5, 1e-5);
    auto right = transform(m, {2, 2, 3});  // +x world is the image's right here
    EXPECT_NEAR(right[0], 1, 1e-6);
    auto up = transform(m, {1, 3, 3});
    EXPECT_NEAR(up[1], 1, 1e-6);
}

TEST(CameraMatrices, WorldToNdcMapsTheFrustumToTheUnitSquareYDown) {
    const orb::Camera camera = looking_down_minus_z();
    const int width = 40, height = 20;
    const Matrix44 m = world_to_ndc(camera, width, height);
    const double distance = 4;
    const double half_height = distance * std::tan(30 * kPi / 180);
    const double half_width = half_height * width / height;

    auto centre = transform(m, {1, 2, 3 - distance});
    EXPECT_NEAR(centre[0], 0.5, 1e-6);
    EXPECT_NEAR(centre[1], 0.5, 1e-6);
    auto top_left = transform(m, {1 - half_width, 2 + half_height, 3 - distance});
    EXPECT_NEAR(top_left[0], 0, 1e-6);
    EXPECT_NEAR(top_left[1], 0, 1e-6);
    auto bottom_right = transform(m, {1 + half_width, 2 - half_height, 3 - distance});
    EXPECT_NEAR(bottom_right[0], 1, 1e-6);
    EXPECT_NEAR(bottom_right[1], 1, 1e-6);
}

// An orthographic camera's view is a rectangle orthographic_height high (its
// width from the image's aspect ratio) at every distance: the matrix is
// affine (W = 1), and the same world offsets reach the same NDC near and far.
TEST(CameraMatrices, OrthographicWorldToNdcIsAffineAndIndependentOfDistance) {
    orb::Camera camera = looking_down_minus_z();
    camera.orthographic_height = 3;
    const int width = 40, height = 20;
    const Matrix44 m = world_to_ndc(camera, width, height);
    EXPECT_EQ(m[0][3], 0.0f);
    EXPECT_EQ(m[1][3], 0.0f);
    EXPECT_EQ(m[2][3], 0.0f);
    EXPECT_EQ(m[3][3], 1.0f);
    const double half_height = 1.5, half_width = half_height * width / height;
    for (const double distance : {0.5, 4.0, 100.0}) {
        auto centre = transform(m, {1, 2, 3 - distance});
        EXPECT_NEAR(centre[0], 0.5, 1e-6);
        EXPECT_NEAR(centre[1], 0.5, 1e-6);
        EXPECT_NEAR(centre[2], distance, 1e-5 * distance);  // Z: the depth along the view
        auto top_left = transform(m, {1 - half_width, 2 + half_height, 3 - distance});
        EXPECT_NEAR(top_left[0], 0, 1e-6);
        EXPECT_NEAR(top_left[1], 0, 1e-6);
        auto bottom_right = transform(m, {1 + half_width, 2 - half_height, 3 - distance});
        EXPECT_NEAR(bottom_right[0], 1, 1e-6);
        EXPECT_NEAR(bottom_right[1], 1, 1e-6);
    }
    // worldToCamera does not depend on the projection.
    EXPECT_EQ(world_to_camera(camera), world_to_camera(looking_down_minus_z()));
}

TEST(CameraMatrices, TheProjectionIsToldFromWorldToNdc) {
    orb::Camera camera = looking_down_minus_z();
    EXPECT_FALSE(is_orthographic(world_to_ndc(camera, 40, 20)));
    // A view along +x, so that the perspective matrix's W column has zeros in it.
    camera.target = {11, 2, 3};
    EXPECT_FALSE(is_orthographic(world_to_ndc(camera, 40, 20)));
    camera.orthographic_height = 2;
    EXPECT_TRUE(is_orthographic(world_to_ndc(camera, 40, 20)));
}
