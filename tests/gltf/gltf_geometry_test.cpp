// Where spheres come from: tessellated meshes under nested transforms,
// instancing, point clouds, implicit shapes, non-spheres, scene selection,
// and external files kept inside the asset's folder.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "gltf_internal.h"
#include "gltf_test_util.h"
#include "orb/scene/error.h"

namespace orb::gltf_test {
namespace {

// Positions are stored as float32: relative error ~1e-7 per vertex.
constexpr double kTol = 1e-5;

void expect_sphere(const Scene& scene, const std::string& name, const Vec3& center, double radius) {
    const Sphere& s = sphere_named(scene, name);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.center[c], center[c], kTol * (1 + radius)) << name << " axis " << c;
    EXPECT_NEAR(s.radius, radius, kTol * radius) << name;
}

class Containers : public ::testing::TestWithParam<std::string> {};

TEST_P(Containers, UvAndIcoSpheresUnderNestedAndMatrixTransforms) {
    const GltfImportResult result = import_generated("nested" + GetParam());
    ASSERT_EQ(result.scene.spheres.size(), 3u);
    // Root T(1,2,3) Rz(90) S(2) * Child T(0,1,0) * mesh centre (0.5,0,0) -> (-1,3,3), radius 2.
    expect_sphere(result.scene, "Child", {-1, 3, 3}, 2);
    // The same mesh under a matrix node: scale 0.5, translation (10,0,0).
    expect_sphere(result.scene, "Matrix", {10.25, 0, 0}, 0.5);
    expect_sphere(result.scene, "Ico", {0, -5, 0}, 1.5);
    EXPECT_TRUE(result.warnings.empty()) << result.warnings.front();
}

TEST_P(Containers, GpuInstancingGivesOneSpherePerInstance) {
    const GltfImportResult result = import_generated("instanced" + GetParam());
    ASSERT_EQ(result.scene.spheres.size(), 3u);
    expect_sphere(result.scene, "Balls#0", {0, 0, -1}, 1);
    expect_sphere(result.scene, "Balls#1", {3, 0, -1}, 2);
    expect_sphere(result.scene, "Balls#2", {0, 3, -1}, 0.5);
}

TEST_P(Containers, PointCloudsUseRadiusAndColourAttributes) {
    const GltfImportResult result = import_generated("points" + GetParam());
    const Scene& scene = result.scene;
    ASSERT_EQ(scene.spheres.size(), 7u);
    // Node T(0,0,1) S(2): _RADIUS is scaled with the node.
    expect_sphere(scene, "Cloud.point0", {0, 0, 1}, 0.2);
    expect_sphere(scene, "Cloud.point1", {2, 0, 1}, 0.4);
    expect_sphere(scene, "Cloud.point2", {0, 2, 1}, 0.6);
    expect_sphere(scene, "Cloud.point3", {0, 0, 3}, 0.8);
    const Vec3 red{1, 0, 0}, half{0.5, 0.5, 0.5};
    EXPECT_EQ(scene.materials[sphere_named(scene, "Cloud.point0").material].color, red);
    EXPECT_EQ(scene.materials[sphere_named(scene, "Cloud.point3").material].color, half);
    // No _RADIUS: 1% of the bounding-box diagonal (4 x 3 box: diagonal 5).
    expect_sphere(scene, "Plain.point1", {14, 0, 0}, 0.05);

    GltfImportOptions options = without_default_light();
    options.point_radius = 0.3;
    const GltfImportResult fixed = import_generated("points" + GetParam(), options);
    expect_sphere(fixed.scene, "Plain.point2", {10, 3, 0}, 0.3);
    expect_sphere(fixed.scene, "Cloud.point1", {2, 0, 1}, 0.4);  // _RADIUS wins
}

TEST_P(Containers, NonSpheresAreSkippedWithOneWarningBoundedOrRefused) {
    const GltfImportResult skipped = import_generated("non_sphere" + GetParam());
    ASSERT_EQ(skipped.scene.spheres.size(), 1u);
    expect_sphere(skipped.scene, "Ball", {0, 0, 0}, 1);
    ASSERT_EQ(skipped.warnings.size(), 1u);
    EXPECT_NE(skipped.warnings[0].find("'Cube'"), std::string::npos) << skipped.warnings[0];

    GltfImportOptions bound = without_default_light();
    bound.non_spheres = NonSpherePolicy::Bound;
    const GltfImportResult bounded = import_generated("non_sphere" + GetParam(), bound);
    ASSERT_EQ(bounded.scene.spheres.size(), 2u);
    expect_sphere(bounded.scene, "Box", {5, 0, 0}, std::sqrt(3.0));

    GltfImportOptions error;
    error.non_spheres = NonSpherePolicy::Error;
    try {
        import_generated("non_sphere" + GetParam(), error);
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("'Cube' is not a sphere"), std::string::npos) << e.what();
    }
}

TEST_P(Containers, SpheresSharingOnePrimitiveAreSplitIntoParts) {
    const GltfImportResult result = import_generated("parts" + GetParam());
    // Row: one indexed primitive; Soup: the same triangles with unshared corners.
    for (const std::string node : {"Row", "Soup"}) {
        const double y = node == "Soup" ? 5 : 0;
        for (int k = 0; k < 3; ++k) expect_sphere(result.scene, node + "." + std::to_string(k), {3.0 * k, y, 0}, 1);
    }
    EXPECT_EQ(result.scene.spheres.size(), 6u);
}

TEST_P(Containers, OpenSurfacesOnASphereAreNotSpheres) {
    const GltfImportResult result = import_generated("parts" + GetParam());
    for (const Sphere& s : result.scene.spheres)
        EXPECT_TRUE(s.name.rfind("Row", 0) == 0 || s.name.rfind("Soup", 0) == 0) << s.name;
    ASSERT_EQ(result.warnings.size(), 1u);
    for (const char* open : {"'Band'", "'Hemisphere'", "'Cap'"})
        EXPECT_NE(result.warnings[0].find(open), std::string::npos) << result.warnings[0];

    GltfImportOptions bound = without_default_light();
    bound.non_spheres = NonSpherePolicy::Bound;
    const Scene bounded = import_generated("parts" + GetParam(), bound).scene;
    EXPECT_EQ(bounded.spheres.size(), 9u);
    // The band spans y in [-sin 45, sin 45] and x, z in [-1, 1]: bounded from the box centre.
    expect_sphere(bounded, "Band", {0, -5, 0}, 1);
}

TEST(GltfGeometry, HemispheresInTwoPrimitivesWeldIntoOneSphere) {
    const GltfImportResult result = import_generated("halves.gltf");
    ASSERT_EQ(result.scene.spheres.size(), 1u);
    expect_sphere(result.scene, "Halves", {0, 0, 2}, 1);
    EXPECT_EQ(result.scene.materials.at(result.scene.spheres[0].material).name, "North");
    EXPECT_TRUE(any_warning_contains(result, "is one sphere in several materials; the first material is used"));
}

INSTANTIATE_TEST_SUITE_P(Gltf, Containers, ::testing::Values(".gltf", "_embedded.gltf", ".glb"));

TEST(GltfGeometry, CompressedGeometryIsRefusedByNameBeforeAccessorChecks) {
    // The Draco asset's accessors have no bufferView: tinygltf alone would
    // call that an invalid accessor.
    const std::pair<const char*, std::string> cases[] = {
        {"draco.gltf", "extensionsRequired[0]: the asset requires KHR_draco_mesh_compression"},
        {"draco.glb", "extensionsRequired[0]: the asset requires KHR_draco_mesh_compression"},
        {"meshopt.glb", "extensionsRequired[1]: the asset requires EXT_meshopt_compression"}};
    for (const auto& [file, message] : cases) {
        try {
            import_generated(file);
            ADD_FAILURE() << file << ": expected an error";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), generated(file) + ": " + message + ", which Orb cannot decode");
        }
    }
}

TEST(GltfGeometry, ConnectedPartsWeldCornersAndCheckClosure) {
    // Two triangles sharing an edge only by position, and a third far away.
    const std::vector<AnimVec3> points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                       {5, 5, 5}, {6, 5, 5}, {5, 6, 5}};
    const auto parts = gltf::connected_parts(points, {{0, 1, 2}, {3, 5, 4}, {6, 7, 8}});
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_EQ(parts[0].points.size(), 4u);  // corners 1 = 3 and 2 = 4 welded
    EXPECT_EQ(parts[0].triangles.size(), 2u);
    EXPECT_EQ(parts[0].source_vertices.size(), 6u);
    EXPECT_FALSE(gltf::is_closed(parts[0].triangles));
    // A tetrahedron is closed, and wraps 4 pi around an inside point.
    const std::vector<AnimVec3> tetra{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    const std::vector<std::array<std::uint32_t, 3>> faces{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    EXPECT_TRUE(gltf::is_closed(faces));
    EXPECT_NEAR(gltf::solid_angle_seen_from({0, 0, 0}, tetra, faces), 4 * std::numbers::pi, 1e-12);
    EXPECT_NEAR(gltf::solid_angle_seen_from({0, 0, 0}, tetra, {faces[0]}), std::numbers::pi, 1e-12);
}

TEST(GltfGeometry, ImplicitSphereShapesOnNodes) {
    const GltfImportResult result = import_generated("implicit_shapes.gltf");
    ASSERT_EQ(result.scene.spheres.size(), 2u);
    expect_sphere(result.scene, "Direct", {1, 1, 1}, 0.75);
    expect_sphere(result.scene, "Collider", {-2, 0, 0}, 1.5);
    EXPECT_TRUE(any_warning_contains(result, "implicit box")) << "the box shape should be named as left out";
}

TEST(GltfGeometry, NonUniformScaleWarnsAndUsesTheLargestAxis) {
    const GltfImportResult result = import_generated("non_uniform.gltf");
    expect_sphere(result.scene, "Squashed", {0, 0, 0}, 2);
    EXPECT_TRUE(any_warning_contains(result, "non-uniform scale"));
    GltfImportOptions strict;
    strict.strict = true;
    EXPECT_THROW(import_generated("non_uniform.gltf", strict), InputError);
}

TEST(GltfGeometry, SphereToleranceDecides) {
    // A UV sphere with 16 segments is exact at its vertices: it passes even a
    // tiny tolerance; a cube never passes, whatever the tolerance.
    GltfImportOptions tight = without_default_light();
    tight.sphere_tolerance = 1e-6;
    EXPECT_EQ(import_generated("nested.gltf", tight).scene.spheres.size(), 3u);
    GltfImportOptions loose = without_default_light();
    loose.sphere_tolerance = 0.5;
    EXPECT_EQ(import_generated("non_sphere.gltf", loose).scene.spheres.size(), 1u);
}

TEST(GltfGeometry, SceneSelectionByIndexAndName) {
    expect_sphere(import_generated("scenes.gltf").scene, "First", {0, 0, 0}, 1);
    GltfImportOptions by_name;
    by_name.scene = "two";
    expect_sphere(import_generated("scenes.gltf", by_name).scene, "Second", {10, 0, 0}, 1);
    GltfImportOptions by_index;
    by_index.scene = "1";
    EXPECT_EQ(import_generated("scenes.gltf", by_index).scene.spheres.at(0).name, "Second");
    GltfImportOptions missing;
    missing.scene = "three";
    EXPECT_THROW(import_generated("scenes.gltf", missing), InputError);
}

TEST(GltfGeometry, ExternalFilesMustExistInsideTheAssetFolder) {
    EXPECT_NO_THROW(import_generated("escape.gltf"));
    for (const char* name : {"sub/escape.gltf", "sub/absolute.gltf", "missing_buffer.gltf"}) {
        try {
            import_generated(name);
            ADD_FAILURE() << name << ": expected an error";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    }
}

TEST(GltfGeometry, SparseAccessorOverZeros) {
    // POSITION: 3 points, all zero except point 1, set to (5,0,0) by a sparse substitution.
    const std::string text = R"({"asset":{"version":"2.0"},
      "buffers":[{"byteLength":16,"uri":"data:application/octet-stream;base64,AQAAAAAAoEAAAAAAAAAAAA=="}],
      "bufferViews":[{"buffer":0,"byteLength":4},{"buffer":0,"byteOffset":4,"byteLength":12}],
      "accessors":[{"componentType":5126,"count":3,"type":"VEC3",
                    "sparse":{"count":1,"indices":{"bufferView":0,"componentType":5125},"values":{"bufferView":1}}}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":0}]}],
      "nodes":[{"name":"P","mesh":0}],"scenes":[{"nodes":[0]}]})";
    GltfImportOptions options = without_default_light();
    options.point_radius = 0.5;
    const Scene scene = import_gltf(text, "sparse.gltf", "", options).scene;
    ASSERT_EQ(scene.spheres.size(), 3u);
    EXPECT_EQ(sphere_named(scene, "P.point0").center, (Vec3{0, 0, 0}));
    EXPECT_EQ(sphere_named(scene, "P.point1").center, (Vec3{5, 0, 0}));
    EXPECT_EQ(sphere_named(scene, "P.point2").center, (Vec3{0, 0, 0}));
}

TEST(GltfGeometry, InstancesTimesPointsBeyondTheLimitAreRefusedUpFront) {
    // A few hundred bytes asking for 10^6 instances of 10^6 points (zero-filled accessors).
    const std::string text = R"({"asset":{"version":"2.0"},
      "extensionsUsed":["EXT_mesh_gpu_instancing"],
      "accessors":[{"componentType":5126,"count":1000000,"type":"VEC3"}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":0}]}],
      "nodes":[{"mesh":0,"extensions":{"EXT_mesh_gpu_instancing":{"attributes":{"TRANSLATION":0}}}}],
      "scenes":[{"nodes":[0]}]})";
    try {
        import_gltf(text, "huge.gltf", "", {});
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("exceed the limit"), std::string::npos) << e.what();
    }
}

TEST(GltfGeometry, MalformedInputIsAnInputError) {
    const char* cases[] = {
        "",
        "{",
        "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"children\":[0]}],\"scenes\":[{\"nodes\":[0]}]}",
        "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"children\":[1]},{\"children\":[0]}],\"scenes\":[{\"nodes\":[0]}]}",
        "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"mesh\":7}],\"scenes\":[{\"nodes\":[0]}]}",
        "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":4,\"uri\":\"data:application/octet-stream;base64,AAAAAA==\"}],"
        "\"bufferViews\":[{\"buffer\":0,\"byteLength\":4}],\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":100,\"type\":\"VEC3\"}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}",
        "glTF\x02\0\0\0\xff\xff\0\0",
    };
    for (const char* text : cases) EXPECT_THROW(import_gltf(text, "bad.gltf", ".", {}), InputError) << text;
    std::string deep = "{\"asset\":{\"version\":\"2.0\"},\"extras\":";
    for (int i = 0; i < 100000; ++i) deep += "[";
    EXPECT_THROW(import_gltf(deep, "deep.gltf", ".", {}), InputError);
}

}  // namespace
}  // namespace orb::gltf_test
