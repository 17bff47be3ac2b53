// The scene around a cloud: shared materials, radii, the automatic camera
// that sees the cloud (its stray points left out), and lights that light it
// without being seen.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "orb/scene/auto_framing.h"
#include "orb/import/ply.h"
#include "ply_builder.h"

namespace orb {
namespace {

using test::make_ply;
using test::PlyTestElement;
const std::vector<std::string> kEncodings{"ascii", "binary_little_endian", "binary_big_endian"};

PlyTestElement xyz_cloud(const std::vector<Vec3>& points) {
    PlyTestElement vertex{"vertex", {{"double", "x", ""}, {"double", "y", ""}, {"double", "z", ""}}, {}};
    for (const Vec3& p : points) vertex.rows.push_back({p[0], p[1], p[2]});
    return vertex;
}

std::size_t emissive_count(const Scene& scene) {
    std::size_t count = 0;
    for (const Sphere& s : scene.spheres)
        if (scene.materials[s.material].emission != Vec3{0, 0, 0}) ++count;
    return count;
}

TEST(PlyScene, ColoursAreArraysBesideOneSharedMaterial) {
    PlyTestElement vertex{"vertex",
                          {{"float", "x", ""}, {"float", "y", ""}, {"float", "z", ""},
                           {"uchar", "red", ""}, {"uchar", "green", ""}, {"uchar", "blue", ""}},
                          {}};
    for (int i = 0; i < 5000; ++i) vertex.rows.push_back({double(i % 71), double(i % 13), double(i / 71), double(i % 256), 7, 255});
    const Scene scene = import_ply(make_ply("binary_little_endian", {vertex}), "c.ply").scene;
    EXPECT_EQ(scene.materials.size(), 1u + 2u);  // every point's material and the two lights'
    const std::vector<float>& colors = scene.sphere_attributes.colors;
    ASSERT_EQ(colors.size(), 3 * scene.spheres.size());
    // sRGB-encoded 8-bit values, decoded (IEC 61966-2-1) to linear floats.
    auto linear = [](double encoded) {
        return static_cast<float>(encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4));
    };
    for (std::size_t i = 0; i < 5000; ++i) {
        EXPECT_EQ(scene.spheres[i].material, 0u);
        EXPECT_FLOAT_EQ(colors[3 * i], linear(double(i % 256) / 255)) << i;
        EXPECT_FLOAT_EQ(colors[3 * i + 1], linear(7.0 / 255)) << i;
        EXPECT_EQ(colors[3 * i + 2], 1.0f) << i;
    }
    // The lights keep their material's (black) colour; their emission is untouched.
    for (std::size_t i = 5000; i < 5002; ++i) {
        EXPECT_EQ(colors[3 * i], 0.0f);
        EXPECT_GT(scene.materials[scene.spheres[i].material].emission[0], 0.0);
    }
    EXPECT_TRUE(scene.sphere_attributes.properties.empty());
}

TEST(PlyScene, OtherVertexPropertiesBecomeSphereProperties) {
    PlyTestElement vertex{"vertex",
                          {{"float", "x", ""}, {"float", "y", ""}, {"float", "z", ""}, {"float", "intensity", ""},
                           {"uchar", "label", ""}, {"double", "nx", ""}, {"uchar", "idx", "int"}},
                          {{0, 0, 0, 0.5, 3, -1, 2, 7, 8}, {1, 2, 3, 1e3, 0, 0.25, 0}}};
    for (const std::string& encoding : kEncodings) {
        const PlyImportResult result = import_ply(make_ply(encoding, {vertex}), "p.ply");
        const std::vector<SphereProperty>& properties = result.scene.sphere_attributes.properties;
        ASSERT_EQ(properties.size(), 3u) << encoding;
        EXPECT_EQ(properties[0], (SphereProperty{"intensity", {0.5f, 1e3f, 0, 0}, {}}));
        EXPECT_EQ(properties[1], (SphereProperty{"label", {3, 0, 0, 0}, {}}));  // and 0 for each light
        EXPECT_EQ(properties[2], (SphereProperty{"nx", {-1, 0.25f, 0, 0}, {}}));
        EXPECT_TRUE(result.scene.sphere_attributes.colors.empty());
        // The list is still read past and named.
        ASSERT_EQ(result.warnings.size(), 1u) << encoding;
        EXPECT_EQ(result.warnings[0], "p.ply: ignored vertex properties (lists): idx");
        ASSERT_EQ(result.notices.size(), 1u);
        EXPECT_EQ(result.notices[0],
                  "p.ply: vertex properties kept as sphere properties (for --color-by, --radius-by): intensity, label, nx");
    }
}

TEST(PlyScene, APropertyASceneCannotHoldIsDroppedWithAWarning) {
    const std::string bytes =
        "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
        "property double big\nproperty float t\nend_header\n0 0 0 1 1\n1 1 1 1e300 3\n";
    const PlyImportResult result = import_ply(bytes, "d.ply");
    ASSERT_EQ(result.scene.sphere_attributes.properties.size(), 1u);
    EXPECT_EQ(result.scene.sphere_attributes.properties[0], (SphereProperty{"t", {1, 3, 0, 0}, {}}));
    EXPECT_EQ(result.warnings, std::vector<std::string>{"d.ply: ignored vertex property 'big': vertex 1 holds inf (a "
                                                        "sphere property must be a finite 32-bit float)"});
}

TEST(PlyScene, PointsWithoutColourAreTheDefaultGrey) {
    const Scene scene = import_ply(make_ply("ascii", {xyz_cloud({{0, 0, 0}, {1, 1, 1}})}), "g.ply").scene;
    EXPECT_EQ(scene.materials.at(scene.spheres[0].material).color, (Vec3{0.8, 0.8, 0.8}));
    EXPECT_EQ(scene.spheres[0].material, scene.spheres[1].material);
    EXPECT_EQ(emissive_count(scene), 2u);
    EXPECT_EQ(scene.render, RenderSettings{});
    EXPECT_EQ(scene.camera.vfov_deg, Camera{}.vfov_deg);
}

TEST(PlyScene, RadiusOptionAndTheDerivedDefault) {
    // 1000 points on a 10x10x10 grid of spacing 1: the derived radius is half the spacing.
    std::vector<Vec3> grid;
    for (int i = 0; i < 1000; ++i) grid.push_back({double(i % 10), double(i / 10 % 10), double(i / 100)});
    const std::string bytes = make_ply("binary_little_endian", {xyz_cloud(grid)});
    const double derived = import_ply(bytes, "grid.ply").scene.spheres[0].radius;
    EXPECT_NEAR(derived, 0.45, 1e-12);  // diagonal 9*sqrt(3) over sqrt(3)*cbrt(1000) = 0.9, halved
    EXPECT_EQ(import_ply(bytes, "grid.ply", {.radius = 0.125}).scene.spheres[999].radius, 0.125);
    // A lone point has no spacing: radius 1.
    EXPECT_EQ(import_ply(make_ply("ascii", {xyz_cloud({{5, 5, 5}})}), "one.ply").scene.spheres[0].radius, 1.0);
}

// Signed distances of a sphere to the four side planes of the camera's view
// frustum (positive inside); the sphere is wholly visible when each >= radius.
std::vector<double> frustum_distances(const Scene& scene, const Vec3& center) {
    const Camera& c = scene.camera;
    auto sub = [](Vec3 a, Vec3 b) { return Vec3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
    auto dot = [](Vec3 a, Vec3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    auto cross = [](Vec3 a, Vec3 b) {
        return Vec3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    auto unit = [&](Vec3 v) {
        const double l = std::sqrt(dot(v, v));
        return Vec3{v[0] / l, v[1] / l, v[2] / l};
    };
    const Vec3 forward = unit(sub(c.target, c.position));
    const Vec3 right = unit(cross(forward, c.up));
    const Vec3 up = cross(right, forward);
    const double half_v = c.vfov_deg * std::numbers::pi / 360;
    const double half_h = std::atan(std::tan(half_v) * scene.render.width / scene.render.height);
    const Vec3 p = sub(center, c.position);
    const double along = dot(p, forward), x = dot(p, right), y = dot(p, up);
    return {along * std::sin(half_h) - x * std::cos(half_h), along * std::sin(half_h) + x * std::cos(half_h),
            along * std::sin(half_v) - y * std::cos(half_v), along * std::sin(half_v) + y * std::cos(half_v)};
}

TEST(PlyScene, TheAutomaticCameraSeesTheCloudButNotItsStrayPointsNorTheLights) {
    std::vector<Vec3> points;
    for (int i = 0; i < 400; ++i)
        points.push_back({100 + 30 * std::sin(i * 0.37), -20 + 5 * std::cos(i * 1.3), 7 * std::sin(i * 0.11) * (i % 7)});
    const Vec3 strays[] = {{1600, -40, 80}, {40, 10, -7000}};  // far from the cloud: left out of the framing
    for (const Vec3& stray : strays) points.push_back(stray);
    for (const std::string& encoding : {std::string("ascii"), std::string("binary_big_endian")}) {
        const Scene scene = import_ply(make_ply(encoding, {xyz_cloud(points)}), "cloud.ply", {.radius = 2}).scene;
        double closest = 1e300;
        for (const Sphere& s : scene.spheres) {
            const bool light = scene.materials[s.material].emission != Vec3{0, 0, 0};
            const bool stray = s.center == strays[0] || s.center == strays[1];
            const std::vector<double> d = frustum_distances(scene, s.center);
            if (stray) continue;
            if (!light) {
                for (double plane : d) {
                    EXPECT_GE(plane, s.radius) << "point at " << s.center[0] << " " << s.center[1];
                    closest = std::min(closest, plane - s.radius);
                }
            } else {
                bool outside = false;
                for (double plane : d) outside = outside || plane < -s.radius;
                EXPECT_TRUE(outside) << scene.materials[s.material].name << " is in view";
            }
        }
        // Every point of the cloud is in view, which is framed around the cloud alone.
        const double distance = std::hypot(scene.camera.position[0] - scene.camera.target[0],
                                           scene.camera.position[1] - scene.camera.target[1],
                                           scene.camera.position[2] - scene.camera.target[2]);
        EXPECT_LT(distance, 200.0) << "framed the cloud, not the strays thousands of units away";
        EXPECT_GT(closest, 0.0);
        // The lights sit around the cloud, not around the strays.
        for (const Sphere& s : scene.spheres) {
            if (scene.materials[s.material].emission == Vec3{0, 0, 0}) continue;
            EXPECT_LT(std::hypot(s.center[0] - 100, s.center[1] + 20, s.center[2]), 300.0);
        }
    }
}

// The camera is the shared framing rule's (orb::frame_spheres, tested in
// tests/scene/auto_framing_test.cpp), seen from 30 degrees above the +z side.
TEST(PlyScene, TheAutomaticCameraIsTheSharedFramingFromThirtyDegreesUp) {
    std::vector<Vec3> points;
    for (int i = 0; i < 300; ++i) points.push_back({std::sin(i * 0.7) * 4, std::cos(i * 0.3), std::sin(i * 1.1)});
    const Scene scene = import_ply(make_ply("ascii", {xyz_cloud(points)}), "cloud.ply", {.radius = 0.05}).scene;
    std::vector<Sphere> cloud(scene.spheres.begin(), scene.spheres.begin() + 300);
    const FramingView view{{0, 0.5, std::sqrt(0.75)}, {0, 1, 0}, scene.camera.vfov_deg, scene.render.width,
                           scene.render.height};
    const Framing framing = *frame_spheres(cloud, view);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(scene.camera.position[c], framing.position[c], 1e-12 * framing.distance);
        EXPECT_EQ(scene.camera.target[c], framing.target[c]);
    }
    EXPECT_NEAR(scene.camera.focus_distance, framing.distance, 1e-12 * framing.distance);
}

}  // namespace
}  // namespace orb
