// orb-import on inputs it cannot make a scene of, as a real executable: a
// format Orb does not read is named (by content, or by extension), and a
// scene that ends with no sphere (a glTF asset of triangle meshes) is an
// error saying what was left out and why, unless --allow-empty. Exit 1 and
// no output file either way. The inputs are real files (tests/data).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "import_cli_fixture.h"
#include "orb/scene/scene_json.h"
#include "run_process.h"

namespace orb {
namespace {

namespace fs = std::filesystem;
using test::ProcessResult;
using ::testing::HasSubstr;

std::string data(const std::string& relative) {
    std::ifstream in(fs::path(ORB_TEST_DATA_DIR) / relative, std::ios::binary);
    EXPECT_TRUE(in) << relative;
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const std::string kReads = "; Orb reads .scn, .gltf/.glb, .ply, .json, .orb, .pdb/.ent, .cif/.mmcif, .xyz/.extxyz, .lammpstrj/.dump, .gro\n";
const std::string kAllowEmpty = "; --allow-empty accepts a scene without spheres\n";

class OrbImportFormatsCli : public test::ImportCliFixture {
protected:
    // Runs orb-import on `name` holding `bytes` with -o out.json; expects
    // exit 1 with exactly `error` and nothing written.
    void expect_refused(const std::string& name, const std::string& bytes, const std::string& error,
                        std::vector<std::string> extra = {}) {
        write(name, bytes);
        std::vector<std::string> args{name, "-o", "out.json"};
        args.insert(args.end(), extra.begin(), extra.end());
        const ProcessResult r = run(args);
        EXPECT_EQ(r.exit_code, 1) << name;
        EXPECT_EQ(r.err, "orb-import: error: " + error) << name;
        EXPECT_EQ(files(), std::vector<std::string>{name}) << "no output (or temporary) left behind";
        fs::remove(dir_ / name);
    }
};

TEST_F(OrbImportFormatsCli, AnObjFileIsNamedByExtensionAndByContent) {
    const std::string obj = data("other-formats/textured_tetrahedron.obj");  // Blender 2.77's OBJ exporter
    expect_refused("tri.obj", obj, "tri.obj: unsupported format (Wavefront OBJ)" + kReads);
    // A wrong or missing extension: the content says what it is, not a .scn or PLY parse error.
    expect_refused("tri.ply", obj, "tri.ply: unsupported format (Wavefront OBJ)" + kReads);
    expect_refused("tri.scn", obj, "tri.scn: unsupported format (Wavefront OBJ)" + kReads);
    expect_refused("tetrahedron", obj, "tetrahedron: unsupported format (Wavefront OBJ)" + kReads);
    const ProcessResult piped = run({"-"}, obj);
    EXPECT_EQ(piped.exit_code, 1);
    EXPECT_EQ(piped.err, "orb-import: error: <stdin>: unsupported format (Wavefront OBJ)" + kReads);
    EXPECT_EQ(piped.out, "");
}

TEST_F(OrbImportFormatsCli, StlAndOffAreNamedByContent) {
    // Blender 2.76's binary STL, whose 80-byte header does not start with "solid".
    expect_refused("cube.glb", data("other-formats/7_8ths_cube.stl"),
                   "cube.glb: unsupported format (STL (binary))" + kReads);
    expect_refused("cube.txt", data("other-formats/comments.off"), "cube.txt: unsupported format (OFF)" + kReads);
}

TEST_F(OrbImportFormatsCli, AFormatKnownOnlyByItsExtensionIsNamed) {
    // A point list of bare numbers: nothing in it says PCD, its name does.
    expect_refused("points.pcd", "665187.52 5648349.89 241.76 117 73 49\n",
                   "points.pcd: unsupported format (PCD (Point Cloud Library))" + kReads);
    // A name an importer decides by gets that reader's error.
    expect_refused("points.xyz", "665187.52 5648349.89 241.76 117 73 49\n",
                   "points.xyz:1: expected the number of atoms of an XYZ frame, got '665187.52 5648349.89 241.76 117 73 49'\n");
    expect_refused("shot.exr", "not really an image", "shot.exr: unsupported format (OpenEXR image)" + kReads);
}

TEST_F(OrbImportFormatsCli, FromOverridesTheGuess) {
    // The reader asked for says what is wrong, in its own terms.
    write("tri.obj", data("other-formats/textured_tetrahedron.obj"));
    const ProcessResult r = run({"tri.obj", "--from", "scn", "-o", "out.json"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_THAT(r.err, HasSubstr("orb-import: error: tri.obj:1:1: "));
    EXPECT_EQ(files(), std::vector<std::string>{"tri.obj"});
}

TEST_F(OrbImportFormatsCli, AGltfAssetOfTriangleMeshesIsRefusedSayingWhy) {
    // Khronos' Box: one cube mesh, nothing sphere-shaped.
    const std::string box = data("gltf-sample-assets/Box/Box.glb");
    expect_refused("Box.glb", box, "Box.glb: no spheres: 1 mesh is not a sphere (Mesh)" + kAllowEmpty);
    expect_refused("Box.glb", box, "Box.glb: no spheres: 1 mesh is not a sphere (Mesh)" + kAllowEmpty,
                   {"--no-default-light", "--to", "scn"});
}

TEST_F(OrbImportFormatsCli, AllowEmptyWritesTheEmptySceneAndSaysWhatWasLeftOut) {
    write("Box.glb", data("gltf-sample-assets/Box/Box.glb"));
    const ProcessResult r = run({"Box.glb", "--allow-empty", "-o", "box.json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr("orb-import: warning: Box.glb: no spheres: 1 mesh is not a sphere (Mesh)\n"));
    std::ifstream in(dir_ / "box.json");
    const Scene scene = load_scene_json(std::string(std::istreambuf_iterator<char>(in), {}), "box.json");
    EXPECT_TRUE(scene.spheres.empty());
}

TEST_F(OrbImportFormatsCli, NonSpheresBoundGivesTheBoxItsBoundingSphere) {
    write("Box.glb", data("gltf-sample-assets/Box/Box.glb"));
    const ProcessResult r = run({"Box.glb", "--non-spheres", "bound", "--no-default-light"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Scene scene = load_scene_json(r.out, "stdout");
    ASSERT_EQ(scene.spheres.size(), 1u);
    // The unit cube's corners are sqrt(3)/2 from its centre.
    EXPECT_NEAR(scene.spheres[0].radius, std::sqrt(3.0) / 2, 1e-6);
}

TEST_F(OrbImportFormatsCli, AnAssetMixingSpheresAndMeshesImportsItsSpheres) {
    // MetalRoughSpheresNoTextures: 98 spheres and four text labels that are meshes.
    write("spheres.glb", data("gltf-sample-assets/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb"));
    const ProcessResult r = run({"spheres.glb"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(load_scene_json(r.out, "stdout").spheres.size(), 98u + 1u);  // and the default key light
    EXPECT_THAT(r.err, HasSubstr("not spheres, left out (--non-spheres bound|error to change): 'Metal' (node 'Metal'), "
                                 "'Non-metal' (node 'Non-metal'), 'Rough' (node 'Rough'), 'Smooth' (node 'Smooth')"));
}

TEST_F(OrbImportFormatsCli, PlyFilesWithoutPointsAreRefused) {
    // trimesh's "valid ply file without vertices", and a header with no element at all.
    expect_refused("empty.ply", data("ply-files/empty.ply"),
                   "empty.ply: no spheres: its 'vertex' element has 0 rows" + kAllowEmpty);
    expect_refused("header.ply", data("ply-files/header-only.ply"),
                   "header.ply: no spheres: it has no 'vertex' element" + kAllowEmpty);
    write("empty.ply", data("ply-files/empty.ply"));
    const ProcessResult allowed = run({"empty.ply", "--allow-empty"});
    EXPECT_EQ(allowed.exit_code, 0) << allowed.err;
    EXPECT_TRUE(load_scene_json(allowed.out, "stdout").spheres.empty());
}

TEST_F(OrbImportFormatsCli, OrbScenesWithoutSpheresAreRefused) {
    expect_refused("s.scn", "camera 0 0 9 0 0 0\nsize 0\n", "s.scn: no spheres: it lists none (size 0)" + kAllowEmpty);
    const std::string json = R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,5], "target": [0,0,0] },
        "environment": { "color": [1, 1, 1] }, "materials": [], "spheres": [] })";
    expect_refused("sky.json", json, "sky.json: no spheres: its \"spheres\" list is empty" + kAllowEmpty);
    write("sky.json", json);
    EXPECT_EQ(run({"sky.json", "--allow-empty"}).exit_code, 0);
}

}  // namespace
}  // namespace orb
