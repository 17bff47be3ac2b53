// Scene files are recognised by their content, not their name.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "orb/scene/error.h"
#include "orb/scene/import.h"

namespace {

using orb::SceneFormat;

TEST(DetectSceneFormat, ByContent) {
    EXPECT_EQ(orb::detect_scene_format("glTF\x02\0\0\0"), SceneFormat::Glb);
    EXPECT_EQ(orb::detect_scene_format(R"({ "asset": { "version": "2.0" } })"), SceneFormat::GltfJson);
    EXPECT_EQ(orb::detect_scene_format("\xEF\xBB\xBF\n { \"format\": \"orb-scene\", \"version\": 1 }"), SceneFormat::OrbJson);
    EXPECT_EQ(orb::detect_scene_format("camera 0 0 0 0 0 1\nsize 0\n"), SceneFormat::Scn);
    EXPECT_EQ(orb::detect_scene_format("  \n"), SceneFormat::Unknown);
}

TEST(DetectSceneFormat, MalformedJsonGoesToTheReaderThatExplainsIt) {
    EXPECT_EQ(orb::detect_scene_format(R"({ "asset": { "version": "2.0" }, )"), SceneFormat::GltfJson);
    EXPECT_EQ(orb::detect_scene_format(R"({ "format": "orb-scene", )"), SceneFormat::OrbJson);
}

TEST(DetectSceneFormat, NamesRoundTrip) {
    for (SceneFormat f : {SceneFormat::OrbJson, SceneFormat::Scn, SceneFormat::GltfJson, SceneFormat::Glb})
        EXPECT_EQ(orb::scene_format_from_name(orb::scene_format_name(f)), f);
    EXPECT_EQ(orb::scene_format_from_name("obj"), SceneFormat::Unknown);
}

TEST(ImportScene, EmptyInputIsAClearError) {
    try {
        orb::import_scene("", "in.scn", ".");
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("in.scn: empty input"), std::string::npos) << e.what();
    }
}

struct Foreign {
    std::string source;
    std::string bytes;
    std::string format;
};

// First bytes or lines as each format's writers produce them.
const std::vector<Foreign> kForeign{
    {"1abc.txt", "HEADER    PLANT PROTEIN                           01-JAN-00   1ABC\nATOM      1  N   MET A   1\n",
     "Protein Data Bank (PDB)"},
    {"water.txt", "3\nwater\nO 0.000 0.000 0.117\nH 0.000 0.757 -0.467\nH 0.000 -0.757 -0.467\n",
     "XYZ (atom coordinates)"},
    {"mmcif", "data_1ABC\n#\n_entry.id 1ABC\n", "CIF / mmCIF"},
    {"model.bin", std::string("Kaydara FBX Binary  \0\x1a\0\xe8\x1c\0\0", 27), "FBX (binary)"},
    {"model.txt", "; FBX 7.4.0 project file\n; Copyright (C) 1997-2010 Autodesk Inc.\n", "FBX (text)"},
    {"cube.txt", "solid cube\n  facet normal 0 0 1\n    outer loop\n", "STL (text)"},
    {"empty.txt", "solid Empty\nendsolid Empty\n", "STL (text)"},
    {"cube.xml", "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\">",
     "COLLADA"},
    {"scene.bin", "BLENDER-v300RENDH", "Blender (.blend)"},
    {"stage.txt", "#usda 1.0\n(\n)\n", "USD (text)"},
    {"world.txt", "#VRML V2.0 utf8\n", "VRML"},
    {"cube.txt", "\tOFF8 6 12 # or nah\n 1.63 0 1.15\n", "OFF"},
    {"cube.mat", "# Blender MTL File: 'None'\nnewmtl Material\nNs 323.999994\n", "Wavefront OBJ material library (.mtl)"},
    {"beauty", std::string("v/1\x01\x02\0\0\0", 8), "OpenEXR image"},
    {"beauty", "\x89PNG\r\n\x1a\n\0\0\0\rIHDR", "PNG image"},
    {"scene.json.gz", std::string("\x1f\x8b\x08\0", 4), "gzip-compressed data"},
    {"points.pcd", "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n", "PCD (Point Cloud Library)"},
};

TEST(ImportScene, FormatsOrbDoesNotReadAreNamedByContent) {
    for (const Foreign& f : kForeign) {
        try {
            orb::import_scene(f.bytes, f.source, ".");
            ADD_FAILURE() << f.format << ": accepted";
        } catch (const orb::InputError& e) {
            EXPECT_EQ(std::string(e.what()), f.source + ": unsupported format (" + f.format +
                                                 "); Orb reads .scn, .gltf/.glb, .ply, .json, .orb");
        }
    }
}

TEST(ImportScene, AChosenFormatIsReadAsChosen) {
    // --from scn: the .scn reader explains what it expected.
    orb::ImportOptions options;
    options.format = SceneFormat::Scn;
    try {
        orb::import_scene("v 0 0 0\nf 1 2 3\n", "tri.obj", ".", options);
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("tri.obj:1:1: ", 0), 0u) << e.what();
    }
}

TEST(ImportScene, AnScnIsNeverTakenForAnotherFormat) {
    // Named like another format, an .scn is still read as one (its content is Orb's).
    orb::ImportOptions options;
    options.allow_empty = true;
    EXPECT_NO_THROW(orb::import_scene("camera 0 0 9 0 0 0\nsize 0\n", "s.obj", ".", options));
}

constexpr const char* kNoSpheres =
    R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,5], "target": [0,0,0] }, "materials": [], "spheres": [] })";

TEST(ImportScene, ASceneWithoutSpheresIsRefusedUnlessAllowed) {
    try {
        orb::import_scene(kNoSpheres, "s.json", ".");
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_STREQ(e.what(),
                     "s.json: no spheres: its \"spheres\" list is empty; --allow-empty accepts a scene without spheres");
    }
    orb::ImportOptions options;
    options.allow_empty = true;
    const auto result = orb::import_scene(kNoSpheres, "s.json", ".", options);
    EXPECT_TRUE(result.scene.spheres.empty());
    EXPECT_TRUE(result.warnings.empty());
    EXPECT_EQ(result.notices, std::vector<std::string>{"s.json: no spheres: its \"spheres\" list is empty"});
}

TEST(ImportScene, AnScnWithoutSpheresIsRefused) {
    try {
        orb::import_scene("camera 0 0 9 0 0 0\nsize 0\n", "s.scn", ".");
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_STREQ(e.what(), "s.scn: no spheres: it lists none (size 0); --allow-empty accepts a scene without spheres");
    }
}

}  // namespace
