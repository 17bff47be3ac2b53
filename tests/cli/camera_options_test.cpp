// The camera options' parsing and checks (orb/cli/camera_options.h,
// orb/cli/orbit_options.h), as every tool that takes them reads them.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include "orb/cli/camera_options.h"
#include "orb/cli/frame_spec.h"
#include "orb/cli/orbit_options.h"
#include "orb/cli/tool_main.h"
#include "orb/scene/auto_framing.h"
#include "orb/scene/error.h"

namespace orb::cli {
namespace {

struct Parsed {
    CameraOptions camera;
    OrbitOptions orbit;
};

// Parses `args` as a tool would; throws CLI::ParseError for a bad value.
Parsed parse(std::vector<std::string> args) {
    Parsed p;
    CLI::App app;
    add_camera_options(app, p.camera);
    add_orbit_options(app, p.orbit);
    std::reverse(args.begin(), args.end());
    app.parse(args);
    return p;
}

std::string parse_error(const std::vector<std::string>& args) {
    try {
        parse(args);
    } catch (const CLI::ParseError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(CameraOptions, ParsesEachOption) {
    const Parsed p = parse({"--camera-position", "1,-2.5,3e2", "--look-at", "0,0,0", "--up", "0,0,1", "--vfov", "35",
                            "--aperture", "0", "--focus-distance", "4.5", "--orthographic", "12", "--orbit", "-90",
                            "--orbit-frames", "1-240"});
    EXPECT_EQ(p.camera.position, (Vec3{1, -2.5, 300}));
    EXPECT_EQ(p.camera.look_at, (Vec3{0, 0, 0}));
    EXPECT_EQ(p.camera.up, (Vec3{0, 0, 1}));
    EXPECT_EQ(p.camera.vfov_deg, 35);
    EXPECT_EQ(p.camera.aperture, 0);
    EXPECT_EQ(p.camera.focus_distance, 4.5);
    EXPECT_EQ(p.camera.orthographic_height, 12);
    EXPECT_EQ(p.orbit.degrees, -90);
    EXPECT_EQ(p.orbit.frames, "1-240");
    EXPECT_EQ(parse({}).camera, CameraOptions{});
    EXPECT_TRUE(parse({"--auto-camera"}).camera.auto_camera);
}

TEST(CameraOptions, AutoCameraFramesTheSpheresThatEmitNothingAndExplicitPlacesWin) {
    Scene scene;
    scene.render.width = 400;
    scene.render.height = 100;
    scene.materials = {Material{}, Material{}};
    scene.materials[1].emission = {5, 5, 5};
    scene.spheres = {Sphere{"a", {-3, 0, 0}, 1, 0}, Sphere{"b", {3, 0, 0}, 1, 0}, Sphere{"lamp", {0, 50, 0}, 5, 1}};
    scene.camera.position = {0, 0, 100};
    scene.camera.target = {0, 0, 90};
    CameraOptions o;
    o.auto_camera = true;
    o.vfov_deg = 30;
    o.focus_distance = 7;
    apply_camera_options(o, scene, 800, 200, "s.json");
    const FramingView view{{0, 0, 10}, {0, 1, 0}, 30, 800, 200};
    const Framing framing = *frame_spheres({scene.spheres[0], scene.spheres[1]}, view);
    EXPECT_EQ(scene.camera.position, framing.position);
    EXPECT_EQ(scene.camera.target, (Vec3{0, 0, 0}));
    EXPECT_EQ(scene.camera.vfov_deg, 30);
    EXPECT_EQ(scene.camera.focus_distance, 7) << "--focus-distance wins over the framing's";
    // Without --auto-camera the scene's spheres are not looked at.
    CameraOptions plain;
    plain.vfov_deg = 20;
    Scene untouched = scene;
    apply_camera_options(plain, untouched, 800, 200, "s.json");
    EXPECT_EQ(untouched.camera.position, scene.camera.position);
    EXPECT_EQ(untouched.camera.vfov_deg, 20);
}

TEST(CameraOptions, BadValuesNameTheOption) {
    for (const auto& [args, message] : std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"--camera-position", "1,2"}, "--camera-position: expected three finite numbers X,Y,Z"},
             {{"--camera-position", "1,2,3,4"}, "--camera-position: expected three finite numbers"},
             {{"--look-at", "1,,3"}, "--look-at: expected three finite numbers"},
             {{"--look-at", "1,nan,3"}, "--look-at: expected three finite numbers"},
             {{"--up", "1e19,0,0"}, "--up: expected three finite numbers X,Y,Z (each of magnitude at most 1e18)"},
             {{"--up", "0,1,0x"}, "--up: expected three finite numbers"},
             {{"--vfov", "0"}, "--vfov: expected degrees in (0, 180), got '0'"},
             {{"--vfov", "180"}, "--vfov: expected degrees in (0, 180)"},
             {{"--vfov", "inf"}, "--vfov: expected degrees in (0, 180)"},
             {{"--aperture", "-0.1"}, "--aperture: expected a lens diameter >= 0"},
             {{"--focus-distance", "0"}, "--focus-distance: expected a distance > 0"},
             {{"--orthographic", "0"}, "--orthographic: expected a height > 0 in scene units, got '0'"},
             {{"--orthographic", "nan"}, "--orthographic: expected a height > 0"},
             {{"--orbit", "nan"}, "--orbit: expected a number of degrees"},
         }) {
        EXPECT_NE(parse_error(args).find(message), std::string::npos) << args[0] << ": " << parse_error(args);
    }
}

TEST(CameraOptions, PerspectiveTurnsAnOrthographicSceneCameraBack) {
    Camera camera;
    camera.orthographic_height = 7;
    apply_camera_options(parse({"--perspective"}).camera, camera, "s.json");
    EXPECT_EQ(camera.orthographic_height, 0);
    camera.orthographic_height = 7;
    apply_camera_options(parse({}).camera, camera, "s.json");
    EXPECT_EQ(camera.orthographic_height, 7) << "without the flag the scene's camera stays";
    EXPECT_NE(parse_error({"--perspective", "--orthographic", "2"}).find("excludes"), std::string::npos)
        << parse_error({"--perspective", "--orthographic", "2"});
}

TEST(CameraOptions, GivenPartsReplaceTheCamerasOthersStay) {
    Camera camera;
    camera.position = {0, 1, 6};
    camera.target = {0, 0.6, 0};
    camera.aperture = 0.3;
    CameraOptions o;
    o.look_at = Vec3{1, 1, 1};
    o.vfov_deg = 20;
    apply_camera_options(o, camera, "s.json");
    EXPECT_EQ(camera.position, (Vec3{0, 1, 6}));
    EXPECT_EQ(camera.target, (Vec3{1, 1, 1}));
    EXPECT_EQ(camera.vfov_deg, 20);
    EXPECT_EQ(camera.aperture, 0.3);
    EXPECT_EQ(camera.orthographic_height, 0);
}

TEST(CameraOptions, ACameraWithoutAViewIsAnErrorNamingTheOption) {
    const auto error = [](const CameraOptions& o) -> std::string {
        Camera camera;  // at (0, 0, 1) looking at the origin, +y up
        try {
            apply_camera_options(o, camera, "s.orb");
        } catch (const InputError& e) {
            return e.what();
        }
        return "(no error)";
    };
    CameraOptions at_camera;
    at_camera.look_at = Vec3{0, 0, 1};
    EXPECT_EQ(error(at_camera), "s.orb: --look-at 0,0,1 is where the scene's camera stands; give --camera-position "
                                "too (the camera needs a direction to look in)");
    CameraOptions at_target;
    at_target.position = Vec3{0, 0, 0};
    EXPECT_NE(error(at_target).find("--camera-position 0,0,0 is the point the scene's camera looks at"), std::string::npos);
    CameraOptions both;
    both.position = both.look_at = Vec3{2, 2, 2};
    EXPECT_NE(error(both).find("--camera-position and --look-at are the same point 2,2,2"), std::string::npos);
    CameraOptions up;
    up.up = Vec3{0, 0, -3};
    EXPECT_NE(error(up).find("s.orb: --up 0,0,-3 is parallel to the view direction 0,0,-1"), std::string::npos);
    CameraOptions zero;
    zero.up = Vec3{0, 0, 0};
    EXPECT_EQ(error(zero), "s.orb: --up must not be the zero vector");
    CameraOptions above;  // looking straight down along the scene's +y up
    above.position = Vec3{0, 5, 0};
    EXPECT_NE(error(above).find("is parallel to the scene's up 0,1,0; give --up"), std::string::npos) << error(above);
}

TEST(OrbitOptions, TheRangeComesFromOrbitFramesElseFromFrames) {
    OrbitOptions o;
    EXPECT_FALSE(resolve_orbit(o, nullptr, false));
    o.degrees = 360;
    const std::string frames = "1-240x2";
    const auto from_frames = resolve_orbit(o, &frames, true);
    ASSERT_TRUE(from_frames);
    EXPECT_EQ(from_frames->first, 1);
    EXPECT_EQ(from_frames->last, 240);  // the range's end, though its step skips it
    EXPECT_EQ(from_frames->angle_deg(121), 180);
    o.frames = "0-9,20";
    const auto given = resolve_orbit(o, &frames, true);
    EXPECT_EQ(given->first, 0);
    EXPECT_EQ(given->last, 20);
    EXPECT_EQ(resolve_orbit(o, nullptr, true)->last, 20);  // --frame N with --orbit-frames
    // What cannot orbit.
    OrbitOptions bare;
    bare.degrees = 90;
    EXPECT_THROW(resolve_orbit(bare, nullptr, false), UsageError);  // a still
    EXPECT_THROW(resolve_orbit(bare, nullptr, true), UsageError);   // --frame N alone
    OrbitOptions lone;
    lone.frames = "1-9";
    EXPECT_THROW(resolve_orbit(lone, nullptr, true), UsageError);
    OrbitOptions bad;
    bad.degrees = 90;
    bad.frames = "9-1";
    try {
        resolve_orbit(bad, nullptr, true);
        FAIL();
    } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("--orbit-frames: frame list '9-1'", 0), 0u) << e.what();
    }
}

TEST(FrameSpecBounds, AreTheLowestAndHighestFramesWritten) {
    const FrameSpec spec = parse_frame_spec("10-20x4,3,7");
    EXPECT_EQ(spec.lowest, 3);
    EXPECT_EQ(spec.highest, 20);
    EXPECT_EQ(parse_frame_spec("5").highest, 5);
}

}  // namespace
}  // namespace orb::cli
