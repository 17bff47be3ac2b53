// Writing .scn: the text, and the list of what .scn cannot express.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "orb/import/scn.h"

namespace orb {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

Scene simple_scene() {
    Scene scene;
    scene.camera.position = {0, 1, 10};
    scene.camera.target = {0, 1, 0};
    scene.camera.vfov_deg = smallptgpu_vfov_deg();
    scene.materials.push_back({"white", MaterialType::Diffuse, {0.75, 0.75, 0.75}, {0, 0, 0}, 1.5});
    scene.materials.push_back({"lamp", MaterialType::Diffuse, {0, 0, 0}, {12, 12, 12}, 1.5});
    scene.materials.push_back({"glass", MaterialType::Dielectric, {1, 1, 1}, {0, 0, 0}, 1.5});
    scene.spheres.push_back({"floor", {0, -1000, 0}, 1000, 0});
    scene.spheres.push_back({"lamp", {0, 5, 0}, 0.5, 1});
    scene.spheres.push_back({"ball", {1, 1, 1}, 1, 2});
    return scene;
}

TEST(ScnWrite, WritesTheBucciarelliLayout) {
    const ScnWriteResult result = write_scn(simple_scene());
    EXPECT_EQ(result.text,
              "camera 0 1 10  0 1 0\n"
              "size 3\n"
              "sphere 1000  0 -1000 0  0 0 0  0.75 0.75 0.75  0\n"
              "sphere 0.5  0 5 0  12 12 12  0 0 0  0\n"
              "sphere 1  1 1 1  0 0 0  1 1 1  2\n");
    EXPECT_TRUE(result.lossy.empty());
}

TEST(ScnWrite, PerSphereColoursAreWrittenAndPropertiesNamedAsLost) {
    Scene scene = simple_scene();
    scene.sphere_attributes.colors = {0.5f, 0.25f, 1, 0, 0, 0, 1, 0.75f, 1};
    ScnWriteResult result = write_scn(scene);
    EXPECT_THAT(result.text, HasSubstr("sphere 1000  0 -1000 0  0 0 0  0.5 0.25 1  0\n"));
    EXPECT_THAT(result.text, HasSubstr("sphere 1  1 1 1  0 0 0  1 0.75 1  2\n"));
    EXPECT_TRUE(result.lossy.empty());
    scene.sphere_attributes.properties = {{"t", {1, 2, 3}, {}}};
    result = write_scn(scene);
    EXPECT_THAT(result.lossy, ElementsAre(HasSubstr("the 1 sphere properties are dropped")));
}

TEST(ScnWrite, FovWithinAHundredthOfADegreeIsSmallptGpus) {
    Scene scene = simple_scene();
    scene.camera.vfov_deg = 42.8711;  // Camera's default, within 0.01 degrees
    EXPECT_TRUE(write_scn(scene).lossy.empty());
    scene.camera.vfov_deg = 40;
    EXPECT_THAT(write_scn(scene).lossy, ElementsAre(HasSubstr("camera vfov_deg 40 is not SmallptGPU's fixed 42.879")));
}

TEST(ScnWrite, AnOrthographicCameraIsNamedInsteadOfItsFieldOfView) {
    Scene scene = simple_scene();
    scene.camera.orthographic_height = 2.5;
    scene.camera.vfov_deg = 40;  // does not apply to an orthographic camera, so not named
    EXPECT_THAT(write_scn(scene).lossy,
                ElementsAre(HasSubstr("camera is orthographic (a view 2.5 units high); .scn cameras are perspective")));
}

TEST(ScnWrite, ListsEverythingScnCannotExpress) {
    Scene scene = simple_scene();
    scene.camera.up = {0, 0, 1};
    scene.camera.aperture = 0.25;
    scene.render.width = 1920;
    scene.render.spp = 256;
    scene.materials[2].ior = 1.33;
    const ScnWriteResult result = write_scn(scene);
    EXPECT_THAT(result.lossy,
                ElementsAre(HasSubstr("camera up vector [0, 0, 1] is not +y"),
                            HasSubstr("camera aperture 0.25 (depth of field) is dropped"),
                            HasSubstr("render settings (width 1920, spp 256) are not stored in .scn"),
                            HasSubstr("material 2 ('glass') is a dielectric with ior 1.33; .scn glass always has ior 1.5")));
    // The text is still written: the caller decides whether losses are fatal.
    EXPECT_THAT(result.text, HasSubstr("size 3\n"));
}

TEST(ScnWrite, AnEnvironmentIsDroppedWithAWarning) {
    for (EnvironmentKind kind : {EnvironmentKind::Color, EnvironmentKind::Map}) {
        Scene scene = simple_scene();
        scene.environment.kind = kind;
        scene.environment.color = {1, 1, 1};
        scene.environment.map = "sky.exr";
        const ScnWriteResult result = write_scn(scene);
        EXPECT_THAT(result.lossy, ElementsAre(HasSubstr("the environment light is dropped; SmallptGPU has none")));
        EXPECT_EQ(result.text, write_scn(simple_scene()).text);
    }
}

TEST(ScnWrite, AnUpVectorAlongPlusYOfAnyLengthIsFine) {
    Scene scene = simple_scene();
    scene.camera.up = {0, 2.5, 0};
    EXPECT_TRUE(write_scn(scene).lossy.empty());
    scene.camera.up = {0, -1, 0};
    EXPECT_EQ(write_scn(scene).lossy.size(), 1u);
}

TEST(ScnWrite, IorOnlyMattersForDielectrics) {
    Scene scene = simple_scene();
    scene.materials[0].ior = 2.0;  // diffuse: ior unused
    EXPECT_TRUE(write_scn(scene).lossy.empty());
}

// .scn has diffuse, mirror and smooth glass: a pbr material becomes the
// closer of the first two, rough glass smooth glass, and both are reported.
TEST(ScnWrite, RoughMaterialsBecomeTheirClosestScnKindAndAreReported) {
    Scene scene = simple_scene();
    scene.materials[2].roughness = 0.3;  // frosted glass
    Material gold{"gold", MaterialType::Pbr, {1, 0.78, 0.34}, {0, 0, 0}, 1.5};
    gold.metallic = 1;
    gold.roughness = 0.2;
    Material plastic{"plastic", MaterialType::Pbr, {0.8, 0.1, 0.1}, {0, 0, 0}, 1.5};
    plastic.roughness = 0.5;
    scene.materials.push_back(gold);
    scene.materials.push_back(plastic);
    scene.spheres.push_back({"gold ball", {3, 1, 1}, 1, 3});
    scene.spheres.push_back({"plastic ball", {5, 1, 1}, 1, 4});
    const ScnWriteResult result = write_scn(scene);
    EXPECT_THAT(result.lossy,
                ElementsAre(HasSubstr("material 2 ('glass') is rough glass (roughness 0.3); .scn glass is smooth"),
                            HasSubstr("material 3 ('gold') is pbr (metallic 1, roughness 0.2); .scn has no such "
                                      "material: written as a mirror"),
                            HasSubstr("material 4 ('plastic') is pbr (metallic 0, roughness 0.5); .scn has no such "
                                      "material: written as diffuse")));
    EXPECT_THAT(result.text, HasSubstr("sphere 1  3 1 1  0 0 0  1 0.78 0.34  1\n"));
    EXPECT_THAT(result.text, HasSubstr("sphere 1  5 1 1  0 0 0  0.8 0.1 0.1  0\n"));
}

TEST(ScnWrite, RefusesDanglingMaterialReferences) {
    Scene scene = simple_scene();
    scene.spheres[1].material = 7;
    EXPECT_THROW(write_scn(scene), std::invalid_argument);
}

TEST(ScnWrite, EmptySceneIsSizeZero) {
    Scene scene = simple_scene();
    scene.spheres.clear();
    scene.materials.clear();
    EXPECT_EQ(write_scn(scene).text, "camera 0 1 10  0 1 0\nsize 0\n");
}

}  // namespace
}  // namespace orb
