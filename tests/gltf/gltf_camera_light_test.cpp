// Cameras (perspective, orthographic, choice, automatic framing) and
// KHR_lights_punctual (emissive spheres of matching intensity).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gltf_test_util.h"
#include "orb/scene/auto_framing.h"
#include "orb/scene/error.h"

namespace orb::gltf_test {
namespace {

constexpr double kPi = std::numbers::pi;

Vec3 direction(const Camera& c) {
    Vec3 d{c.target[0] - c.position[0], c.target[1] - c.position[1], c.target[2] - c.position[2]};
    const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (double& x : d) x /= n;
    return d;
}

void expect_vec(const Vec3& got, const Vec3& want, double tol = 1e-9) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tol) << "component " << c;
}

class Cameras : public ::testing::TestWithParam<std::string> {};

TEST_P(Cameras, FirstPerspectiveCameraWithItsNodeTransform) {
    const Scene scene = import_generated("cameras" + GetParam()).scene;
    expect_vec(scene.camera.position, {0, 0, 10});
    expect_vec(direction(scene.camera), {0, 0, -1});
    expect_vec(scene.camera.up, {0, 1, 0});
    EXPECT_NEAR(scene.camera.vfov_deg, 0.5 * 180 / kPi, 1e-12);
    EXPECT_EQ(scene.render.width, 960);  // aspectRatio 2 at the default height
    EXPECT_EQ(scene.render.height, 480);
    // The target is the scene's centre along the view.
    expect_vec(scene.camera.target, {0, 0, 0});
}

TEST_P(Cameras, ChosenByIndexCameraNameOrNodeName) {
    for (const char* key : {"1", "Side", "SideCam"}) {
        GltfImportOptions options;
        options.camera = key;
        const Scene scene = import_generated("cameras" + GetParam(), options).scene;
        expect_vec(scene.camera.position, {10, 0, 0});
        expect_vec(direction(scene.camera), {-1, 0, 0});  // -z turned 90 degrees about +y
        expect_vec(scene.camera.up, {0, 1, 0});
        EXPECT_NEAR(scene.camera.vfov_deg, 0.8 * 180 / kPi, 1e-12) << key;
        EXPECT_EQ(scene.render.width, 640) << "no aspectRatio: the default size";
    }
    GltfImportOptions missing;
    missing.camera = "Nope";
    EXPECT_THROW(import_generated("cameras" + GetParam(), missing), InputError);
}

// ymag is half the view's height; xmag/ymag sets the default image's aspect
// ratio, as aspectRatio does for a perspective camera.
TEST_P(Cameras, OrthographicKeepsTwiceYmagAsTheViewsHeight) {
    const GltfImportResult result = import_generated("ortho" + GetParam());
    const Scene& scene = result.scene;
    EXPECT_EQ(scene.camera.orthographic_height, 3.0);  // 2 * ymag 1.5
    EXPECT_EQ(scene.render.width, 640);                // xmag/ymag = 2/1.5 at the default height
    EXPECT_EQ(scene.render.height, 480);
    expect_vec(scene.camera.position, {0, 0, 10});
    expect_vec(direction(scene.camera), {0, 0, -1});
    expect_vec(scene.camera.up, {0, 1, 0});
    expect_vec(scene.camera.target, {0, 0, 0});
    EXPECT_FALSE(any_warning_contains(result, "xmag")) << "the image holds xmag/ymag exactly";

    // A ratio no image holds: the view keeps its height, and a warning says what became of its width.
    GltfImportOptions wide;
    wide.camera = "Wide";
    const GltfImportResult clamped = import_generated("ortho" + GetParam(), wide);
    EXPECT_EQ(clamped.scene.camera.orthographic_height, 2.0);
    EXPECT_EQ(clamped.scene.render.width, 65536);
    expect_vec(direction(clamped.scene.camera), {-1, 0, 0});
    EXPECT_TRUE(any_warning_contains(clamped, "camera 'Wide': orthographic xmag/ymag 1000 needs an image 480000 pixels "
                                              "wide; it is 65536x480, so the view keeps its height 2 ymag = 2 and is "
                                              "273.06666666666666 wide, not 2 xmag = 2000"));
    wide.strict = true;
    EXPECT_THROW(import_generated("ortho" + GetParam(), wide), InputError);
}

TEST_P(Cameras, AMirroringOrthographicCameraIsAClearError) {
    GltfImportOptions options;
    options.camera = "Mirrored";
    try {
        import_generated("ortho" + GetParam(), options);
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("camera 'Mirrored': orthographic ymag -1 must be > 0"), std::string::npos)
            << e.what();
    }
}

TEST_P(Cameras, NoCameraFramesTheBoundsFromPlusZ) {
    const Scene scene = import_generated("no_camera" + GetParam()).scene;
    // Spheres of radius 1 at x = 0 and 4: bounds [-1,5]x[-1,1]x[-1,1].
    expect_vec(scene.camera.target, {2, 0, 0}, 1e-6);
    expect_vec(direction(scene.camera), {0, 0, -1}, 1e-9);
    expect_vec(scene.camera.up, {0, 1, 0});
    // Every sphere lies wholly inside the vertical and horizontal field of
    // view narrowed by the framing margin, and one touches it (the framing
    // rule itself is tested in tests/scene/auto_framing_test.cpp).
    const double tan_v = std::tan(scene.camera.vfov_deg * kPi / 360) / (1 + kFramingMargin);
    const double half_v = std::atan(tan_v);
    const double half_h = std::atan(tan_v * scene.render.width / scene.render.height);
    double closest = 1e300;
    for (const Sphere& s : scene.spheres) {
        const double depth = scene.camera.position[2] - s.center[2];
        ASSERT_GT(depth, s.radius);
        const double angular_radius = std::asin(s.radius / std::hypot(depth, s.center[0] - 2));
        const double room_h = half_h - (std::atan(std::fabs(s.center[0] - 2) / depth) + angular_radius);
        const double room_v = half_v - (std::atan(std::fabs(s.center[1]) / depth) + std::asin(s.radius / depth));
        EXPECT_GE(room_h, -1e-9);
        EXPECT_GE(room_v, -1e-9);
        closest = std::min({closest, room_h, room_v});
    }
    EXPECT_NEAR(closest, 0, 1e-9) << "framed tightly";
}

INSTANTIATE_TEST_SUITE_P(Gltf, Cameras, ::testing::Values(".gltf", "_embedded.gltf", ".glb"));

class Lights : public ::testing::TestWithParam<std::string> {};

TEST_P(Lights, PointLightIsASphereOfMatchingIntensity) {
    GltfImportOptions options;
    options.light_radius = 0.1;
    const GltfImportResult result = import_generated("point_light" + GetParam(), options);
    const Sphere& bulb = sphere_named(result.scene, "Bulb");
    expect_vec(bulb.center, {0, 5, 0}, 1e-6);
    EXPECT_DOUBLE_EQ(bulb.radius, 0.1);
    const Material& m = result.scene.materials.at(bulb.material);
    expect_vec(m.color, {0, 0, 0});
    // glTF: 100 cd x colour (1, 0.5, 0.25) = 100/683 W/sr x colour. A sphere of
    // radiance L shows pi r^2 of area in every direction, so its intensity is L pi r^2.
    const Vec3 intensity{100 / 683.0, 50 / 683.0, 25 / 683.0};
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(m.emission[c], intensity[c] / (kPi * 0.01), 1e-9 * m.emission[c]);
        EXPECT_NEAR(m.emission[c] * kPi * bulb.radius * bulb.radius, intensity[c], 1e-9 * intensity[c]);
    }
    EXPECT_TRUE(result.warnings.empty());
}

TEST_P(Lights, DefaultLightRadiusIsOnePercentOfTheSceneDiagonal) {
    const Scene scene = import_generated("point_light" + GetParam()).scene;
    // Ball [-1,1]^3 and the light at (0,5,0): box 2 x 6 x 2.
    // The ball's radius comes from float32 vertices: relative error ~1e-7.
    const double radius = 0.01 * std::sqrt(4.0 + 36 + 4);
    const Sphere& bulb = sphere_named(scene, "Bulb");
    EXPECT_NEAR(bulb.radius, radius, 1e-6 * radius);
    EXPECT_NEAR(scene.materials.at(bulb.material).emission[0] * kPi * bulb.radius * bulb.radius, 100 / 683.0, 1e-12);
}

TEST_P(Lights, PhotometricUnitsMatchBlendersLampPower) {
    GltfImportOptions options;
    options.light_radius = 0.5;
    const Scene scene = import_generated("point_light" + GetParam(), options).scene;
    const Sphere& bulb = sphere_named(scene, "Bulb");
    // Blender imports 100 cd as a lamp of 100 x 4 pi / 683 W. A Lambertian
    // sphere of radius R and radiance L emits 4 pi^2 R^2 L.
    const double blender_watts = 100 * 4 * kPi / 683;
    const double L = scene.materials.at(bulb.material).emission[0];
    EXPECT_NEAR(4 * kPi * kPi * 0.25 * L, blender_watts, 1e-12 * blender_watts);
    EXPECT_NEAR(L, 100 / (683 * kPi * 0.25), 1e-12);
}

TEST_P(Lights, RadiometricUnitsTakeOneCandelaAsOneWattPerSteradian) {
    GltfImportOptions options;
    options.light_radius = 0.1;
    options.light_units = LightUnits::Radiometric;
    options.directional_lights = true;
    const Scene point = import_generated("point_light" + GetParam(), options).scene;
    const Sphere& bulb = sphere_named(point, "Bulb");
    EXPECT_NEAR(point.materials.at(bulb.material).emission[1], 50 / (kPi * 0.01), 1e-9);
    const Scene all = import_generated("all_lights" + GetParam(), options).scene;
    const Sphere& sun = sphere_named(all, "Sun");
    const double sine = sun.radius / std::hypot(sun.center[0], sun.center[1], sun.center[2]);
    EXPECT_NEAR(all.materials.at(sun.material).emission[0] * kPi * sine * sine, 3.0, 1e-6);
}

TEST_P(Lights, SpotAndDirectionalLightsWarn) {
    const GltfImportResult result = import_generated("all_lights" + GetParam());
    EXPECT_TRUE(any_warning_contains(result, ": ignored: spot cone angles of 1 light"));
    EXPECT_TRUE(any_warning_contains(result, "'Sun' is directional"));
    const Sphere& spot = sphere_named(result.scene, "Spot");
    expect_vec(spot.center, {0, -5, 0}, 1e-6);
    for (const Sphere& s : result.scene.spheres) EXPECT_NE(s.name, "Sun");
    GltfImportOptions strict;
    strict.strict = true;
    EXPECT_THROW(import_generated("all_lights" + GetParam(), strict), InputError);
}

TEST_P(Lights, DirectionalLightAsADistantEmitterGivesItsIlluminance) {
    GltfImportOptions options;
    options.directional_lights = true;
    const GltfImportResult result = import_generated("all_lights" + GetParam(), options);
    const Sphere& sun = sphere_named(result.scene, "Sun");
    const Scene& scene = result.scene;
    // The light shines down -y, so the emitter is straight up (+y) from the scene.
    EXPECT_GT(sun.center[1], 100 * sun.radius / 10);
    EXPECT_NEAR(sun.center[0], 0, 1e-6 * sun.center[1]);
    EXPECT_NEAR(sun.center[2], 0, 1e-6 * sun.center[1]);
    // Irradiance at the scene from a sphere of radiance L: E = L pi (r/d)^2 =
    // 3 lux = 3/683 W/m^2 (Blender's sun strength for 3 lux).
    const double d = std::hypot(sun.center[0], sun.center[1], sun.center[2]);
    const double sine = sun.radius / d;
    const Material& m = scene.materials.at(sun.material);
    EXPECT_NEAR(m.emission[0] * kPi * sine * sine, 3.0 / 683, 1e-9);  // the scene is centred on the origin
}

TEST_P(Lights, AutomaticCameraFramesTheSceneNotTheDistantSun) {
    GltfImportOptions options;
    options.directional_lights = true;
    const Scene scene = import_generated("all_lights" + GetParam(), options).scene;
    const Sphere& sun = sphere_named(scene, "Sun");
    // Ball [-1,1]^3, Bulb at (0,5,0) and Spot at (0,-5,0) of equal radius r:
    // the box is [-1,1] x [-5-r,5+r] x [-1,1], centred on the origin.
    expect_vec(scene.camera.target, {0, 0, 0}, 1e-6);
    // The framing rule (orb::frame_spheres) applied to every sphere but the sun.
    const FramingView view{{0, 0, 1}, {0, 1, 0}, scene.camera.vfov_deg, scene.render.width, scene.render.height};
    const auto framing = frame_spheres(scene.spheres, view, [&](std::size_t i) { return &scene.spheres[i] == &sun; });
    ASSERT_TRUE(framing);
    EXPECT_EQ(framing->framed, scene.spheres.size() - 1);
    expect_vec(scene.camera.position, framing->position, 1e-12);
    // The same framing as without the sun.
    const Scene sunless = import_generated("all_lights" + GetParam()).scene;
    expect_vec(scene.camera.position, sunless.camera.position, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Gltf, Lights, ::testing::Values(".gltf", "_embedded.gltf", ".glb"));

}  // namespace
}  // namespace orb::gltf_test
