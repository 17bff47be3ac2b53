// The camera from orb-render's command line (docs/orb-render.md, "Camera"):
// the options replace parts of the scene's camera on every scene form, the
// binary one included, and render exactly what the same camera written into
// the scene renders; --orbit turns it frame by frame, the same whichever
// process renders a frame; a changed camera is another render to
// --skip-existing; a camera without a view is one clear error.
#include <filesystem>
#include <fstream>

#include "cli_fixture.h"
#include "orb/scene/scene_binary.h"

using namespace orb::test;
using orb::exr::testing::expect_same_pixels;
using orb::exr::testing::read_raw_exr;
namespace fs = std::filesystem;

namespace {

int count_lines(const std::string& text, const std::string& what) {
    int n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

class RenderCamera : public RenderCli {
protected:
    std::string write_binary(const orb::Scene& scene, const std::string& name = "scene.orb") const {
        const std::string file = path(name);
        std::ofstream(file, std::ios::binary) << orb::write_scene_binary(scene);
        return file;
    }
};

}  // namespace

TEST_F(RenderCamera, OptionsOnABinarySceneRenderWhatTheSameCameraInTheSceneRenders) {
    const std::string binary = write_binary(small_scene());
    orb::Scene moved = small_scene();
    moved.camera.position = {2.5, 1.5, 4.5};
    moved.camera.target = {-0.25, 0.5, 0};
    moved.camera.up = {0.1, 1, 0};
    moved.camera.vfov_deg = 55;
    moved.camera.aperture = 0.2;
    moved.camera.focus_distance = 4.75;
    const std::string json = write_scene(moved, "moved.json");

    const auto options = render({binary, "-o", path("options.exr"), "--seed", "5", "--spp", "3", "--camera-position",
                                 "2.5,1.5,4.5", "--look-at", "-0.25,0.5,0", "--up", "0.1,1,0", "--vfov", "55",
                                 "--aperture", "0.2", "--focus-distance", "4.75"});
    ASSERT_EQ(options.exit_code, 0) << options.err;
    const auto written = render({json, "-o", path("written.exr"), "--seed", "5", "--spp", "3"});
    ASSERT_EQ(written.exit_code, 0) << written.err;
    expect_same_pixels(read_raw_exr(path("options.exr")), read_raw_exr(path("written.exr")));
    // The same image of another scene file, but the same render: the same scene hash and camera.
    const auto a = orb::exr::read_film_exr(path("options.exr")).metadata;
    const auto b = orb::exr::read_film_exr(path("written.exr")).metadata;
    EXPECT_EQ(a.scene_hash, b.scene_hash);
    EXPECT_EQ(a.world_to_camera, b.world_to_camera);
    EXPECT_EQ(a.world_to_ndc, b.world_to_ndc);
}

TEST_F(RenderCamera, AnOptionGivenAloneKeepsTheRestOfTheScenesCamera) {
    const std::string binary = write_binary(small_scene());
    orb::Scene aimed = small_scene();
    aimed.camera.target = {0.9, 0.5, 0.5};  // at the mirror ball, from the scene's position
    const std::string json = write_scene(aimed, "aimed.json");
    ASSERT_EQ(render({binary, "-o", path("look.exr"), "--spp", "2", "--look-at", "0.9,0.5,0.5"}).exit_code, 0);
    ASSERT_EQ(render({json, "-o", path("written.exr"), "--spp", "2"}).exit_code, 0);
    expect_same_pixels(read_raw_exr(path("look.exr")), read_raw_exr(path("written.exr")));
}

// small_scene's camera stands at (0, 1, 6) and looks at (0, 0.6, 0), +y up:
// a quarter turn about +y through the target takes it to (6, 1, 0), half a turn to (0, 1, -6).
TEST_F(RenderCamera, OrbitFramesAreTheCameraTurnedAboutTheLookAtPoint) {
    const std::string scene = write_binary(small_scene());
    const std::vector<std::string> common{scene, "--spp", "2", "--seed", "9", "--same-seed"};
    auto args = common;
    args.insert(args.end(), {"--orbit", "360", "--frames", "0-3", "-o", path("orbit.%d.exr")});
    const auto orbit = render(args);
    ASSERT_EQ(orbit.exit_code, 0) << orbit.err;

    const auto explicitly = [&](const std::string& frame, const std::string& position, const std::string& out) {
        auto a = common;
        a.insert(a.end(), {"--frame", frame, "--camera-position", position, "-o", path(out)});
        const auto run = render(a);
        EXPECT_EQ(run.exit_code, 0) << run.err;
    };
    explicitly("0", "0,1,6", "at0.exr");
    explicitly("1", "6,1,0", "at90.exr");
    explicitly("2", "0,1,-6", "at180.exr");
    expect_same_pixels(read_raw_exr(path("orbit.0.exr")), read_raw_exr(path("at0.exr")));
    expect_same_pixels(read_raw_exr(path("orbit.1.exr")), read_raw_exr(path("at90.exr")));
    expect_same_pixels(read_raw_exr(path("orbit.2.exr")), read_raw_exr(path("at180.exr")));
    // 360 degrees over 4 frames loops: frame 3 is at 270 degrees, not back at the start.
    EXPECT_NE(orb::exr::read_film_exr(path("orbit.3.exr")).metadata.world_to_camera,
              orb::exr::read_film_exr(path("orbit.0.exr")).metadata.world_to_camera);
}

TEST_F(RenderCamera, AnOrbitFrameIsTheSameWhicheverRunRendersIt) {
    const std::string scene = write_scene(moving_ball_scene());  // animated: the orbit turns each pose's camera
    const std::vector<std::string> common{scene, "--spp", "2", "--orbit", "120"};
    auto all = common;
    all.insert(all.end(), {"--frames", "10-21", "-o", path("all.%d.exr")});
    ASSERT_EQ(render(all).exit_code, 0);
    // One frame alone, given the whole animation's frames.
    auto one = common;
    one.insert(one.end(), {"--frame", "14", "--orbit-frames", "10-21", "-o", path("one.%d.exr")});
    const auto single = render(one);
    ASSERT_EQ(single.exit_code, 0) << single.err;
    expect_same_pixels(read_raw_exr(path("all.14.exr")), read_raw_exr(path("one.14.exr")));
    // A stepped preview lies on the same timeline: 10-21x4 renders 10, 14, 18 of the range 10 ... 21.
    auto preview = common;
    preview.insert(preview.end(), {"--frames", "10-21x4", "-o", path("preview.%d.exr")});
    ASSERT_EQ(render(preview).exit_code, 0);
    expect_same_pixels(read_raw_exr(path("all.14.exr")), read_raw_exr(path("preview.14.exr")));
    expect_same_pixels(read_raw_exr(path("all.18.exr")), read_raw_exr(path("preview.18.exr")));
    // --claim workers split the same frames and render the same images.
    auto claim = common;
    claim.insert(claim.end(), {"--frames", "10-21", "--claim", "-o", path("all.%d.exr")});
    fs::remove(path("all.18.exr"));
    const auto worker = render(claim);
    ASSERT_EQ(worker.exit_code, 0) << worker.err;
    EXPECT_EQ(count_lines(worker.err, "skipped"), 11) << worker.err;
    expect_same_pixels(read_raw_exr(path("all.18.exr")), read_raw_exr(path("preview.18.exr")));
}

TEST_F(RenderCamera, AnotherCameraIsAnotherRenderToSkipExisting) {
    const std::string scene = write_binary(small_scene());
    const auto run = [&](const std::vector<std::string>& camera) {
        std::vector<std::string> args{scene, "--spp", "1", "--frames", "0-1", "-o", path("f.%d.exr"), "--skip-existing"};
        args.insert(args.end(), camera.begin(), camera.end());
        return render(args);
    };
    ASSERT_EQ(run({"--orbit", "90"}).exit_code, 0);
    const auto same = run({"--orbit", "90"});
    EXPECT_EQ(count_lines(same.err, "finished (1 spp); skipped"), 2) << same.err;
    // Another orbit: frame 0 is still at 0 degrees, frame 1 moves.
    const auto wider = run({"--orbit", "120"});
    EXPECT_EQ(count_lines(wider.err, "finished (1 spp); skipped"), 1) << wider.err;
    EXPECT_EQ(count_lines(wider.err, "frame 1: " + path("f.1.exr") + ": rendered from another camera"), 1) << wider.err;
    // No orbit but a wider lens: both frames again; then both finished.
    const auto lens = run({"--vfov", "60"});
    EXPECT_EQ(count_lines(lens.err, "rendered from another camera"), 2) << lens.err;
    EXPECT_EQ(count_lines(run({"--vfov", "60"}).err, "finished (1 spp); skipped"), 2);
    // --missing agrees: nothing missing for this camera, both frames for another.
    const auto missing = render({scene, "--spp", "1", "--frames", "0-1", "-o", path("f.%d.exr"), "--vfov", "60", "--missing"});
    EXPECT_EQ(missing.out, "");
    const auto moved = render({scene, "--spp", "1", "--frames", "0-1", "-o", path("f.%d.exr"), "--up", "0.2,1,0", "--missing"});
    EXPECT_EQ(moved.out, "0\n1\n");
}

TEST_F(RenderCamera, ACameraWithoutAViewIsOneErrorNamingTheOption) {
    const std::string scene = write_binary(small_scene());
    const auto look = render({scene, "-o", path("out.exr"), "--look-at", "0,1,6"});
    EXPECT_EQ(look.exit_code, 1);
    EXPECT_NE(look.err.find("scene.orb: --look-at 0,1,6 is where the scene's camera stands; give --camera-position too"),
              std::string::npos)
        << look.err;
    const auto up = render({scene, "-o", path("out.exr"), "--up", "0,-0.4,-6"});
    EXPECT_EQ(up.exit_code, 1);
    EXPECT_NE(up.err.find("--up 0,-0.4,-6 is parallel to the view direction"), std::string::npos) << up.err;
    const auto both = render({scene, "-o", path("out.exr"), "--camera-position", "1,2,3", "--look-at", "1,2,3"});
    EXPECT_EQ(both.exit_code, 1);
    EXPECT_NE(both.err.find("--camera-position and --look-at are the same point 1,2,3"), std::string::npos) << both.err;
    // Values wrong on their own are usage errors naming the option.
    const std::vector<std::pair<std::vector<std::string>, std::string>> usage{
        {{"--vfov", "180"}, "--vfov: expected degrees in (0, 180), got '180'"},
        {{"--vfov", "nan"}, "--vfov: expected degrees in (0, 180), got 'nan'"},
        {{"--camera-position", "1,2"}, "--camera-position: expected three finite numbers X,Y,Z"},
        {{"--look-at", "1,inf,2"}, "--look-at: expected three finite numbers X,Y,Z"},
        {{"--aperture", "-1"}, "--aperture: expected a lens diameter >= 0, got '-1'"},
        {{"--focus-distance", "0"}, "--focus-distance: expected a distance > 0, got '0'"},
        {{"--orthographic", "-2"}, "--orthographic: expected a height > 0 in scene units, got '-2'"},
        {{"--orbit", "90"}, "--orbit turns the camera over the frames of an animation"},
        {{"--orbit", "90", "--frame", "3"}, "--orbit with --frame N needs --orbit-frames LIST"},
        {{"--orbit-frames", "1-9"}, "--orbit-frames LIST goes with --orbit DEGREES"},
    };
    for (const auto& [args, message] : usage) {
        std::vector<std::string> argv{scene, "-o", path("out.exr")};
        argv.insert(argv.end(), args.begin(), args.end());
        const auto run = render(argv);
        EXPECT_EQ(run.exit_code, 2) << args[0];
        EXPECT_NE(run.err.find(message), std::string::npos) << run.err;
    }
    EXPECT_EQ(files(), std::vector<std::string>{"scene.orb"});
}
