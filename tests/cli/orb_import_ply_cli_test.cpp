// orb-import on PLY point clouds, as a real executable: recognised by
// content, --from ply, --radius, and one clear error per malformed file with
// exit status 1 and no output left behind.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "orb/scene/auto_framing.h"
#include "orb/import/ply.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"
#include "import_cli_fixture.h"
#include "run_process.h"

namespace orb {
namespace {

namespace fs = std::filesystem;
using test::ProcessResult;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

const std::string kCloud =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 1\nproperty list uchar int "
    "vertex_indices\nend_header\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 255 0 0\n3 0 1 2\n";

class OrbImportPlyCli : public test::ImportCliFixture {};

TEST_F(OrbImportPlyCli, PlyFileToOrbJson) {
    write("cloud.ply", kCloud);
    const ProcessResult r = run({"cloud.ply", "--radius", "0.25"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "orb-import: warning: cloud.ply: ignored elements: face (1 row)\n");
    const Scene scene = load_scene_json(r.out, "stdout");
    EXPECT_EQ(scene, import_ply(kCloud, "cloud.ply", {.radius = 0.25}).scene);
    EXPECT_EQ(scene.spheres.size(), 3u + 2u);
    EXPECT_EQ(scene.materials.size(), 1u + 2u);  // the points' (their colours are per sphere), two lights
    EXPECT_EQ(scene.sphere_attributes.colors.size(), 3u * (3u + 2u));
    EXPECT_EQ(scene.spheres[0].radius, 0.25);
}

TEST_F(OrbImportPlyCli, ColourAndSizeByAVertexProperty) {
    const std::string cloud =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "property float temperature\nend_header\n0 0 0 300\n1 0 0 350\n0 1 0 400\n";
    write("md.ply", cloud);
    const ProcessResult r = run({"md.ply", "--color-by", "temperature", "--colormap", "greys", "--radius-by",
                                 "temperature", "--radius-range", "0.1,0.2", "--material", "plastic", "-o", "md.orb"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr("orb-import: md.ply: --color-by temperature: greys from 300 to 400\n"));
    std::ifstream in(dir_ / "md.orb", std::ios::binary);
    const Scene scene = load_scene_binary(std::string(std::istreambuf_iterator<char>(in), {}), "md.orb");
    ASSERT_EQ(scene.sphere_attributes.colors.size(), 3u * (3u + 2u));
    EXPECT_EQ(scene.sphere_attributes.colors[0], 1.0f);  // greys: white at the minimum
    EXPECT_EQ(scene.sphere_attributes.colors[6], 0.0f);  // black at the maximum
    EXPECT_DOUBLE_EQ(scene.spheres[1].radius, 0.15);
    EXPECT_EQ(scene.materials[0].type, MaterialType::Pbr);

    // An unknown property: one error naming what the file has, and no output.
    const ProcessResult unknown = run({"md.ply", "--color-by", "temp", "-o", "bad.orb"});
    EXPECT_EQ(unknown.exit_code, 1);
    EXPECT_THAT(unknown.err, HasSubstr("orb-import: error: md.ply: --color-by temp: no such sphere property (the scene "
                                       "has: temperature)\n"));
    EXPECT_FALSE(fs::exists(dir_ / "bad.orb"));
    // Malformed options are usage errors, before anything is read.
    EXPECT_EQ(run({"md.ply", "--color-by", "temperature", "--colormap", "jet"}).exit_code, 2);
    EXPECT_EQ(run({"md.ply", "--color-by", "temperature", "--color-range", "5,1"}).exit_code, 2);
    EXPECT_EQ(run({"md.ply", "--radius-by", "temperature"}).exit_code, 2);
    EXPECT_EQ(run({"md.ply", "--material", "glass"}).exit_code, 2);
}

TEST_F(OrbImportPlyCli, StdinIsRecognisedByContentAndFromPlyWorks) {
    const ProcessResult detected = run({"-"}, kCloud);
    ASSERT_EQ(detected.exit_code, 0) << detected.err;
    const ProcessResult named = run({"-", "--from", "ply"}, kCloud);
    EXPECT_EQ(named.out, detected.out);
}

TEST_F(OrbImportPlyCli, ANonPositiveRadiusIsAUsageError) {
    write("cloud.ply", kCloud);
    EXPECT_EQ(run({"cloud.ply", "--radius", "-1"}).exit_code, 2);
    EXPECT_EQ(run({"cloud.ply", "--radius", "0"}).exit_code, 2);
}

std::string data(const std::string& relative) {
    std::ifstream in(fs::path(ORB_TEST_DATA_DIR) / relative, std::ios::binary);
    EXPECT_TRUE(in) << relative;
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Real writers' files (tests/data/ply-files/README.md): what Orb does not read is named, never dropped silently.
TEST_F(OrbImportPlyCli, BlendersPointCloudImportsWithoutAWord) {
    write("points.ply", data("ply-files/blender-2.91-points.ply"));  // x y z, and an empty face element
    const ProcessResult r = run({"points.ply"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.err, IsEmpty());
    EXPECT_EQ(load_scene_json(r.out, "stdout").spheres.size(), 8u + 2u);  // the cube's corners and two lights
}

TEST_F(OrbImportPlyCli, PropertiesAndElementsOrbDoesNotReadAreNamed) {
    write("plane.ply", data("ply-files/blender-2.82-plane.ply"));  // normals, texture coordinates, a face
    const ProcessResult r = run({"plane.ply"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err,
              "orb-import: warning: plane.ply: ignored elements: face (1 row)\n"
              "orb-import: warning: plane.ply: vertex properties kept as sphere properties (for --color-by, "
              "--radius-by): nx, ny, nz, s, t\n");
    const Scene plane = load_scene_json(r.out, "stdout");
    EXPECT_EQ(plane.spheres.size(), 4u + 2u);
    EXPECT_EQ(plane.sphere_attributes.properties.size(), 5u);

    write("lists.ply", data("ply-files/point-lists.ply"));  // an element of two list properties and a float
    const ProcessResult lists = run({"lists.ply"});
    ASSERT_EQ(lists.exit_code, 0) << lists.err;
    EXPECT_EQ(lists.err, "orb-import: warning: lists.ply: ignored elements: point_list (2 rows)\n");
}

TEST_F(OrbImportPlyCli, StrictRefusesWhatWouldBeLost) {
    write("plane.ply", data("ply-files/blender-2.82-plane.ply"));
    const ProcessResult r = run({"plane.ply", "--strict", "-o", "plane.json"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "orb-import: error: plane.ply would lose information (--strict):\n"
              "  plane.ply: ignored elements: face (1 row)\n");
    EXPECT_EQ(files(), std::vector<std::string>{"plane.ply"});
}

TEST_F(OrbImportPlyCli, ABlender24HeaderLineWithoutKeywordIsReadAsAComment) {
    // Blender 2.4x's PLY exporter (ply_export.py, "Blender: 241") wrote its
    // credit line without the "comment" keyword, and float32/uint8 types.
    const std::string lamp =
        "ply\nformat ascii 1.0\nCreated by Blender3D 249 - www.blender.org, source file: lamp.blend\n"
        "element vertex 2\nproperty float32 x\nproperty float32 y\nproperty float32 z\nproperty float32 nx\n"
        "property float32 ny\nproperty float32 nz\nelement face 0\nproperty list uint8 int32 vertex_indices\n"
        "end_header\n0 0 0 0 0 1\n1 0 0 0 0 1\n";
    write("lamp.ply", lamp);
    // A comment loses nothing, nor do the normals (kept as sphere properties): not an error.
    const ProcessResult r = run({"lamp.ply", "--strict"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const ProcessResult relaxed = run({"lamp.ply"});
    ASSERT_EQ(relaxed.exit_code, 0) << relaxed.err;
    EXPECT_EQ(relaxed.err,
              "orb-import: warning: lamp.ply: header line 3 (\"Created by Blender3D 249 - www.blender.org, source "
              "file: lamp.blend\") has no PLY keyword and was read as a comment\n"
              "orb-import: warning: lamp.ply: vertex properties kept as sphere properties (for --color-by, "
              "--radius-by): nx, ny, nz\n");
    EXPECT_EQ(load_scene_json(relaxed.out, "stdout").spheres.size(), 2u + 2u);
}

struct BadPly {
    const char* name;
    std::string bytes;
    std::string message;
};

void PrintTo(const BadPly& bad, std::ostream* os) { *os << bad.name; }

class OrbImportBadPly : public OrbImportPlyCli, public ::testing::WithParamInterface<BadPly> {};

TEST_P(OrbImportBadPly, OneMessageExit1AndNoOutput) {
    write("bad.ply", GetParam().bytes);
    const ProcessResult r = run({"bad.ply", "-o", "out.json"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "orb-import: error: " + GetParam().message + "\n");
    EXPECT_THAT(r.out, IsEmpty());
    EXPECT_EQ(files(), std::vector<std::string>{"bad.ply"});  // no output, no temporaries
}

const std::string kXyz = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n";

INSTANTIATE_TEST_SUITE_P(
    EveryErrorClass, OrbImportBadPly,
    ::testing::Values(
        // A .ply name picks the PLY reader even when the magic is wrong.
        BadPly{"bad_magic", "PLY\nformat ascii 1.0\n", "bad.ply:1: not a PLY file (it must start with the line \"ply\")"},
        BadPly{"bad_header_line", "ply\nformat ascii 1.0\nelement vertex\n", "bad.ply:3: expected \"element NAME COUNT\""},
        BadPly{"unknown_type", "ply\nformat ascii 1.0\nelement vertex 1\nproperty half x\nend_header\n",
               "bad.ply:4: unknown property type 'half' (expected char, uchar, short, ushort, int, uint, float, double "
               "or int8 ... float64)"},
        BadPly{"missing_y", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float z\nend_header\n",
               "bad.ply:3: element 'vertex' has no 'y' property (x, y and z are required)"},
        BadPly{"truncated", kXyz + "end_header\n1 2 3\n4\n", "bad.ply: vertex 1 property 'y': the data ends early (the file is truncated)"},
        BadPly{"count_larger_than_file",
               "ply\nformat binary_big_endian 1.0\nelement vertex 4000000000\nproperty double x\nproperty double y\n"
               "property double z\nend_header\n0123456789abcdef01234567",
               "bad.ply:3: element 'vertex' declares 4000000000 rows of at least 24 bytes, more than the 24 bytes of "
               "data left in the file"},
        BadPly{"count_overflows", "ply\nformat ascii 1.0\nelement vertex 18446744073709551616\nend_header\n",
               "bad.ply:3: element 'vertex' count 18446744073709551616 overflows"},
        BadPly{"nan", kXyz + "end_header\n1 2 3\n4 nan 6\n", "bad.ply: vertex 1 property 'y': must be finite, got nan"},
        BadPly{"inf", kXyz + "end_header\n1 2 -inf\n4 5 6\n", "bad.ply: vertex 0 property 'z': must be finite, got -inf"},
        BadPly{"negative_radius", kXyz + "property double radius\nend_header\n1 2 3 0.5\n4 5 6 -0.5\n",
               "bad.ply: vertex 1 property 'radius': must be > 0, got -0.5"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace orb

namespace orb {
namespace {

// The Stanford bunny's 453 vertices (tests/data/stanford-bunny/README.md)
// with three stray points far from it, as a scan picks them up: the
// automatic camera, the point radius and the lights are the bunny's own.
class OrbImportBunny : public test::ImportCliFixture {};

TEST_F(OrbImportBunny, StrayPointsDoNotShrinkTheScan) {
    std::ifstream in(std::string(ORB_TEST_DATA_DIR) + "/stanford-bunny/bun_zipper_res4_points.ply");
    const std::string bunny{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    ASSERT_THAT(bunny, HasSubstr("element vertex 453\n"));
    std::string strays = bunny;
    strays.replace(strays.find("element vertex 453"), 18, "element vertex 456");
    strays += "1.5 0.1 0 0.5 0.5\n-0.02 3 -0.4 0.5 0.5\n0.2 -0.9 2.2 0.5 0.5\n";
    write("bunny.ply", bunny);
    write("strays.ply", strays);
    const ProcessResult alone = run({"bunny.ply"});
    const ProcessResult with_strays = run({"strays.ply"});
    ASSERT_EQ(alone.exit_code, 0) << alone.err;
    ASSERT_EQ(with_strays.exit_code, 0) << with_strays.err;
    const Scene a = load_scene_json(alone.out, "bunny");
    const Scene b = load_scene_json(with_strays.out, "strays");
    // The strays are so far out that the bunny's core box is the same: the same camera and lights.
    EXPECT_EQ(a.camera, b.camera);
    EXPECT_EQ(a.spheres[0].radius, b.spheres[0].radius);
    EXPECT_EQ(a.spheres[a.spheres.size() - 1], b.spheres[b.spheres.size() - 1]);
    // The bunny is about 0.16 units across: framed from about 0.3 away, not from metres.
    const double distance = std::hypot(a.camera.position[0] - a.camera.target[0],
                                       a.camera.position[1] - a.camera.target[1],
                                       a.camera.position[2] - a.camera.target[2]);
    EXPECT_GT(distance, 0.15);
    EXPECT_LT(distance, 0.5);
}

// The camera options of orb-import move the camera of any scene, the binary
// form included, and leave the rest as it was.
TEST_F(OrbImportBunny, CameraOptionsMoveTheCameraOfABinaryScene) {
    fs::copy_file(std::string(ORB_TEST_DATA_DIR) + "/stanford-bunny/bun_zipper_res4_points.ply", dir_ / "bunny.ply");
    ASSERT_EQ(run({"bunny.ply", "-o", "bunny.orb"}).exit_code, 0);
    const ProcessResult moved =
        run({"bunny.orb", "--camera-position", "0.3,0.2,0.3", "--look-at", "-0.02,0.1,0", "--vfov", "30",
             "--orthographic", "0.25"});
    ASSERT_EQ(moved.exit_code, 0) << moved.err;
    const ProcessResult plain = run({"bunny.orb"});
    Scene expected = load_scene_json(plain.out, "plain");
    expected.camera.position = {0.3, 0.2, 0.3};
    expected.camera.target = {-0.02, 0.1, 0};
    expected.camera.vfov_deg = 30;
    Scene got = load_scene_json(moved.out, "moved");
    // The orthographic height is set on the scene; its JSON form is another change's.
    expected.camera.orthographic_height = got.camera.orthographic_height;
    EXPECT_EQ(got, expected);

    const ProcessResult bad = run({"bunny.orb", "--look-at", "0.3,0.2,0.3", "--camera-position", "0.3,0.2,0.3",
                                   "-o", "out.orb"});
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_THAT(bad.err, HasSubstr("bunny.orb: --camera-position and --look-at are the same point 0.3,0.2,0.3"));
    EXPECT_FALSE(fs::exists(dir_ / "out.orb"));
}

}  // namespace
}  // namespace orb

namespace orb {
namespace {

// --auto-camera frames a scene anew by the automatic camera's rule, from its
// camera's direction, leaving its lights out; explicit options win.
TEST_F(OrbImportBunny, AutoCameraFramesTheSpheresAgainAndExplicitOptionsWin) {
    fs::copy_file(std::string(ORB_TEST_DATA_DIR) + "/stanford-bunny/bun_zipper_res4_points.ply", dir_ / "bunny.ply");
    const ProcessResult imported = run({"bunny.ply"});
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
    Scene far = load_scene_json(imported.out, "bunny");
    const Camera automatic = far.camera;
    // A camera far away (as the old framing left a scan with stray points), looking from the side.
    far.camera.position = {40, 0.1, 0};
    far.camera.target = {0, 0.1, 0};
    write("far.json", write_scene_json(far));

    const ProcessResult again = run({"far.json", "--auto-camera", "--vfov", "30"});
    ASSERT_EQ(again.exit_code, 0) << again.err;
    const Camera got = load_scene_json(again.out, "again").camera;
    const FramingView view{{40, 0, 0}, {0, 1, 0}, 30, far.render.width, far.render.height};
    const auto point = [&](std::size_t i) { return far.materials[far.spheres[i].material].emission != Vec3{0, 0, 0}; };
    const Framing expected = *frame_spheres(far.spheres, view, point);
    EXPECT_EQ(expected.framed, 453u) << "the two lights are not framed";
    EXPECT_EQ(got.position, expected.position);
    EXPECT_EQ(got.target, expected.target);
    EXPECT_EQ(got.focus_distance, expected.distance);
    EXPECT_EQ(got.vfov_deg, 30);
    EXPECT_EQ(got.target, automatic.target) << "the same framed box as at import";

    // An explicit --look-at wins over the automatic one; the automatic position stays.
    const ProcessResult aimed = run({"far.json", "--auto-camera", "--vfov", "30", "--look-at", "0,0.15,0"});
    ASSERT_EQ(aimed.exit_code, 0) << aimed.err;
    const Camera aimed_camera = load_scene_json(aimed.out, "aimed").camera;
    EXPECT_EQ(aimed_camera.target, (Vec3{0, 0.15, 0}));
    EXPECT_EQ(aimed_camera.position, expected.position);
}

}  // namespace
}  // namespace orb
