// The turntable's camera (orb/scene/camera_orbit.h): turned about the up
// axis through the target, exact at quarter turns, and the angle of a frame.
#include <gtest/gtest.h>

#include <cmath>

#include "orb/scene/camera_orbit.h"

namespace orb {
namespace {

Camera front() {
    Camera c;
    c.position = {0, 0, 5};
    c.target = {0, 0, 0};
    c.up = {0, 1, 0};
    return c;
}

TEST(CameraOrbit, QuarterTurnsAreExactAndRightHanded) {
    // Counter-clockwise seen from +y: +z goes to +x, then -z, then -x.
    EXPECT_EQ(orbit_camera(front(), 90).position, (Vec3{5, 0, 0}));
    EXPECT_EQ(orbit_camera(front(), 180).position, (Vec3{0, 0, -5}));
    EXPECT_EQ(orbit_camera(front(), 270).position, (Vec3{-5, 0, 0}));
    EXPECT_EQ(orbit_camera(front(), -90).position, (Vec3{-5, 0, 0}));
    EXPECT_EQ(orbit_camera(front(), 360).position, (Vec3{0, 0, 5}));
    EXPECT_EQ(orbit_camera(front(), 0), front());
}

TEST(CameraOrbit, TurnsAboutTheTargetAlongUpKeepingTheRest) {
    Camera c = front();
    c.position = {1, 4, 2};
    c.target = {1, 1, -2};  // 3 below, 4 in front
    c.up = {0, 2, 0};       // any length
    c.vfov_deg = 30;
    c.aperture = 0.5;
    c.focus_distance = 5;
    const Camera turned = orbit_camera(c, 30);
    const double angle = 30 * std::acos(-1.0) / 180;
    EXPECT_NEAR(turned.position[0], 1 + 4 * std::sin(angle), 1e-12);
    EXPECT_NEAR(turned.position[1], 4, 1e-12);  // the elevation stays
    EXPECT_NEAR(turned.position[2], -2 + 4 * std::cos(angle), 1e-12);
    EXPECT_EQ(turned.target, c.target);
    EXPECT_EQ(turned.up, c.up);
    EXPECT_EQ(turned.vfov_deg, 30);
    EXPECT_EQ(turned.aperture, 0.5);
    EXPECT_EQ(turned.focus_distance, 5);

    // A tilted axis: the distance to the target and the angle to the axis stay.
    c.up = {1, 1, 0};
    const Camera tilted = orbit_camera(c, 77);
    const auto offset = [](const Camera& k) {
        return Vec3{k.position[0] - k.target[0], k.position[1] - k.target[1], k.position[2] - k.target[2]};
    };
    const Vec3 a = offset(c), b = offset(tilted);
    EXPECT_NEAR(std::hypot(a[0], a[1], a[2]), std::hypot(b[0], b[1], b[2]), 1e-12);
    EXPECT_NEAR(a[0] + a[1], b[0] + b[1], 1e-12);
}

TEST(CameraOrbit, TheAngleOfAFrameSpansTheRangeAsOneLoop) {
    // 360 degrees over frames 1 ... 4: 0, 90, 180, 270; frame 5 would be back at the start.
    EXPECT_EQ(orbit_angle_deg(360, 1, 1, 4), 0);
    EXPECT_EQ(orbit_angle_deg(360, 2, 1, 4), 90);
    EXPECT_EQ(orbit_angle_deg(360, 4, 1, 4), 270);
    EXPECT_EQ(orbit_angle_deg(360, 5, 1, 4), 360);
    EXPECT_EQ(orbit_angle_deg(-90, 3, 0, 9), -27);
    EXPECT_EQ(orbit_angle_deg(45, 7, 7, 7), 0);  // a single frame stays put
}

}  // namespace
}  // namespace orb
