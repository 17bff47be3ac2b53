// The camera's frame, view and lens (orb/scene/camera_frame.h), which the
// renderer's device camera and the EXR's camera matrices both read.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "orb/scene/camera_frame.h"

namespace orb {
namespace {

void expect_orthonormal(const CameraFrame& f) {
    EXPECT_NEAR(vec3::length(f.forward), 1.0, 1e-15);
    EXPECT_NEAR(vec3::length(f.right), 1.0, 1e-15);
    EXPECT_NEAR(vec3::length(f.up), 1.0, 1e-15);
    EXPECT_NEAR(vec3::dot(f.forward, f.right), 0.0, 1e-15);
    EXPECT_NEAR(vec3::dot(f.forward, f.up), 0.0, 1e-15);
    EXPECT_NEAR(vec3::dot(f.right, f.up), 0.0, 1e-15);
    // Right-handed like the scene: right x up is backwards, towards the camera.
    const Vec3 back = vec3::cross(f.right, f.up);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], -f.forward[c], 1e-15);
}

TEST(CameraFrame, LooksAtTheTargetWithTheScenesUpMadeOrthogonal) {
    Camera camera;
    camera.position = {1, 2, 3};
    camera.target = {1, 2, -7};
    camera.up = {0, 2, 1};  // any length, not orthogonal to the view
    const CameraFrame f = camera_frame(camera);
    EXPECT_EQ(f.target_distance, 10.0);
    EXPECT_EQ(f.forward, (Vec3{0, 0, -1}));
    EXPECT_EQ(f.right, (Vec3{1, 0, 0}));
    EXPECT_EQ(f.up, (Vec3{0, 1, 0}));
    expect_orthonormal(f);

    camera.position = {3, -1, 2};
    camera.target = {-2, 4, 0.5};
    camera.up = {0.2, 1, -0.3};
    const CameraFrame g = camera_frame(camera);
    expect_orthonormal(g);
    EXPECT_NEAR(g.target_distance, std::sqrt(25.0 + 25.0 + 2.25), 1e-14);
    // up stays in the plane of the view and the scene's up, on its side.
    EXPECT_NEAR(vec3::dot(vec3::cross(g.forward, camera.up), g.up), 0.0, 1e-15);
    EXPECT_GT(vec3::dot(g.up, camera.up), 0.0);
}

TEST(CameraFrame, AnUpAlongTheViewFallsBackToTheWorldAxisLeastAlignedWithIt) {
    Camera camera;
    camera.position = {0, 5, 0};
    camera.target = {0.5, 0, 0.25};  // mostly down; z is the axis least along it
    camera.up = {-0.1, 1, -0.05};    // parallel to the view
    const CameraFrame f = camera_frame(camera);
    expect_orthonormal(f);
    // right = forward x z, normalised: perpendicular to z.
    EXPECT_NEAR(f.right[2], 0.0, 1e-15);
    const Vec3 expected = vec3::normalized(vec3::cross(f.forward, {0, 0, 1}));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f.right[c], expected[c], 1e-15);
}

TEST(CameraFrame, ACameraWithoutADirectionIsRefused) {
    Camera camera;
    camera.target = camera.position;
    EXPECT_THROW(camera_frame(camera), std::runtime_error);
    camera.target = {0, 0, INFINITY};
    EXPECT_THROW(camera_frame(camera), std::runtime_error);
}

TEST(CameraFrame, PerspectiveExtentsAreTheHalfAnglesTangentsAndTheImagesAspect) {
    Camera camera;
    camera.vfov_deg = 60;
    const ViewExtents view = view_extents(camera, 40, 20);
    EXPECT_FALSE(view.orthographic);
    EXPECT_NEAR(view.half_height, std::tan(std::numbers::pi / 6), 1e-15);
    EXPECT_EQ(view.half_width, view.half_height * 2);
}

TEST(CameraFrame, OrthographicExtentsAreTheViewInSceneUnits) {
    Camera camera;
    camera.orthographic_height = 3;
    const ViewExtents view = view_extents(camera, 30, 20);
    EXPECT_TRUE(view.orthographic);
    EXPECT_EQ(view.half_height, 1.5);
    EXPECT_EQ(view.half_width, 2.25);
    EXPECT_THROW(view_extents(camera, 0, 20), std::invalid_argument);
    EXPECT_THROW(view_extents(camera, 30, -1), std::invalid_argument);
}

TEST(CameraFrame, TheLensIsHalfTheApertureFocusedAtItsDistanceOrTheTarget) {
    Camera camera;
    camera.position = {0, 0, 4};
    camera.target = {0, 0, 0};
    camera.aperture = 0.5;
    camera.focus_distance = 2;
    const CameraFrame f = camera_frame(camera);
    EXPECT_EQ(camera_lens(camera, f).radius, 0.25);
    EXPECT_EQ(camera_lens(camera, f).focus_distance, 2.0);
    camera.focus_distance = 0;  // not the scene format's, but a lens must focus somewhere
    EXPECT_EQ(camera_lens(camera, f).focus_distance, 4.0);
    camera.aperture = -1;
    EXPECT_EQ(camera_lens(camera, f).radius, 0.0);
}

}  // namespace
}  // namespace orb
