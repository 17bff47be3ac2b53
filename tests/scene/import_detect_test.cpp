// Scene files are recognised by their content, not their name.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "orb/scene/error.h"
#include "orb/import/gltf.h"
#include "orb/import/import.h"
#include "orb/import/ply.h"
#include "orb/import/importers.h"
#include "orb/import/molecular.h"

namespace {

// The name of the importer that recognises the bytes; "" when none does.
std::string recognised(std::string_view bytes) {
    const orb::SceneImporter* importer = orb::recognise_scene(bytes);
    return importer ? std::string(importer->name) : std::string();
}

TEST(DetectSceneFormat, ByContent) {
    EXPECT_EQ(recognised("glTF\x02\0\0\0"), "gltf");
    EXPECT_EQ(recognised(R"({ "asset": { "version": "2.0" } })"), "gltf");
    EXPECT_EQ(recognised("\xEF\xBB\xBF\n { \"format\": \"orb-scene\", \"version\": 1 }"), "orb");
    EXPECT_EQ(recognised("camera 0 0 0 0 0 1\nsize 0\n"), "scn");
    EXPECT_EQ(recognised("ply\nformat ascii 1.0\n"), "ply");
    EXPECT_EQ(recognised("  \n"), "");
    EXPECT_EQ(recognised("v 0 0 0\n"), "");  // text the .scn reader would only fall back to
}

TEST(DetectSceneFormat, MalformedJsonGoesToTheReaderThatExplainsIt) {
    EXPECT_EQ(recognised(R"({ "asset": { "version": "2.0" }, )"), "gltf");
    EXPECT_EQ(recognised(R"({ "format": "orb-scene", )"), "orb");
}

TEST(SceneImporters, EveryWordFindsItsImporter) {
    const std::vector<std::string> words = orb::scene_format_words();
    EXPECT_EQ(words, (std::vector<std::string>{"scn", "gltf", "glb", "ply", "orb", "json", "orb-binary", "pdb", "ent",
                                               "mmcif", "cif", "xyz", "extxyz", "lammps-dump", "lammpstrj", "gro"}));
    for (const std::string& word : words) EXPECT_NE(orb::find_scene_importer(word), nullptr) << word;
    EXPECT_EQ(orb::find_scene_importer("glb"), orb::find_scene_importer("gltf"));
    EXPECT_EQ(orb::find_scene_importer("json"), orb::find_scene_importer("orb"));
    EXPECT_EQ(orb::find_scene_importer("obj"), nullptr);
}

// Each importer's option group, as a tool's command line gets them all.
TEST(SceneImporters, EachOptionGroupAddsItsOwnOptionsToACommandLine) {
    CLI::App app;
    orb::ImportOptions options;
    std::size_t groups = 0;
    for (const orb::ImportOptionGroup* group : orb::import_option_groups()) {
        ++groups;
        ASSERT_NE(group->add, nullptr) << group->heading;
        const std::size_t before = app.get_options().size();
        group->add(app, options);  // CLI11 throws for a name another group has
        const std::vector<CLI::Option*> added = app.get_options();
        EXPECT_GT(added.size(), before) << group->heading;
        for (std::size_t i = before; i < added.size(); ++i)
            EXPECT_EQ(added[i]->get_group(), group->heading) << added[i]->get_name();
    }
    EXPECT_EQ(groups, 3u);  // glTF, PLY, and the molecular readers' one, each once
    for (const orb::SceneImporter& importer : orb::scene_importers()) {
        if (!importer.options) continue;
        const std::vector<const orb::ImportOptionGroup*> all = orb::import_option_groups();
        EXPECT_NE(std::find(all.begin(), all.end(), importer.options), all.end()) << importer.name;
    }
    app.parse(std::vector<std::string>{"bound", "--non-spheres", "0.5", "--radius", "--cell", "covalent", "--atom-radius",
                                       "2", "--gltf-scene"});  // reversed, as CLI11 takes a vector
    EXPECT_EQ(options.of<orb::GltfImportOptions>().scene, "2");
    EXPECT_EQ(options.of<orb::GltfImportOptions>().non_spheres, orb::NonSpherePolicy::Bound);
    EXPECT_EQ(options.of<orb::PlyImportOptions>().radius, 0.5);
    EXPECT_TRUE(options.of<orb::MolecularImportOptions>().cell);
    EXPECT_EQ(options.of<orb::MolecularImportOptions>().radius, orb::AtomRadius::Covalent);
}

TEST(SceneImporters, TheirNumericOptionsRefuseWhatIsNotAFiniteNumberInRange) {
    for (const std::vector<std::string>& args : {std::vector<std::string>{"nan", "--radius"}, {"inf", "--radius"},
                                                 {"-1", "--light-radius"}, {"2", "--sphere-tolerance"},
                                                 {"1x", "--point-radius"}}) {
        CLI::App app;
        orb::ImportOptions options;
        for (const orb::ImportOptionGroup* group : orb::import_option_groups()) group->add(app, options);
        EXPECT_THROW(app.parse(std::vector<std::string>(args)), CLI::ValidationError) << args[1] << " " << args[0];
    }
}

TEST(SceneImporters, EveryEntryIsComplete) {
    std::set<std::string> seen;
    for (const orb::SceneImporter& importer : orb::scene_importers()) {
        EXPECT_FALSE(importer.name.empty());
        EXPECT_FALSE(importer.description.empty()) << importer.name;
        EXPECT_EQ(importer.description.find('\n'), std::string_view::npos) << importer.name;
        EXPECT_NE(importer.recognise, nullptr) << importer.name;
        // One scene (read) or frames (open_frames, which import_scene reads a frame of), never both.
        EXPECT_NE(importer.read == nullptr, importer.open_frames == nullptr) << importer.name;
        EXPECT_TRUE(importer.open_frames || !importer.reads_series) << importer.name;
        EXPECT_FALSE(importer.no_spheres.empty()) << importer.name;
        for (std::string_view extension : importer.extensions) {
            EXPECT_TRUE(extension.starts_with('.')) << importer.name;
            EXPECT_TRUE(seen.insert(std::string(extension)).second) << extension << " listed twice";
        }
        EXPECT_TRUE(importer.extensions.size() || !importer.extension_decides) << importer.name;
        EXPECT_TRUE(seen.insert(std::string(importer.name)).second) << importer.name << " named twice";
        for (std::string_view alias : importer.aliases)
            EXPECT_TRUE(seen.insert(std::string(alias)).second) << alias << " named twice";
    }
    EXPECT_EQ(orb::readable_file_names(), ".scn, .gltf/.glb, .ply, .json, .orb, .pdb/.ent, .cif/.mmcif, .xyz/.extxyz, .lammpstrj/.dump, .gro");
}

TEST(SceneImporters, TheFormatsOfFramesAreTheTablesEntries) {
    // The molecular and particle formats are entries like any other: the
    // frame functions find them through the table, and only them.
    std::vector<std::string> frames, series;
    for (const orb::SceneImporter& importer : orb::scene_importers()) {
        if (importer.open_frames) frames.emplace_back(importer.name);
        if (importer.reads_series) series.emplace_back(importer.name);
        EXPECT_EQ(orb::find_frame_importer(importer.name), importer.open_frames ? &importer : nullptr) << importer.name;
    }
    EXPECT_EQ(frames, (std::vector<std::string>{"pdb", "mmcif", "xyz", "lammps-dump", "gro"}));
    EXPECT_EQ(series, (std::vector<std::string>{"xyz", "lammps-dump", "gro"}));
    EXPECT_EQ(orb::find_frame_importer("lammpstrj"), orb::find_scene_importer("lammps-dump"));  // an alias
    EXPECT_EQ(orb::recognise_molecular_file("ITEM: TIMESTEP\n0\n", "d"), "lammps-dump");
    EXPECT_EQ(orb::recognise_molecular_file("2\ncomment\nH 0 0 0\nH 0 0 1\n", "x"), "xyz");
    EXPECT_EQ(orb::recognise_molecular_file("camera 0 0 0 0 0 1\n", "c.scn"), "");
}

TEST(SceneImporters, TheExtensionDecidesOnlyForItsImporters) {
    EXPECT_EQ(orb::scene_importer_for_path("dir.v2/model.GLB"), orb::find_scene_importer("gltf"));
    EXPECT_EQ(orb::scene_importer_for_path("cloud.ply"), orb::find_scene_importer("ply"));
    EXPECT_EQ(orb::scene_importer_for_path("scene.json"), nullptr);  // content decides: '{' or not
    EXPECT_EQ(orb::scene_importer_for_path("tri.obj"), nullptr);
    EXPECT_TRUE(orb::is_importer_extension("scene.JSON"));
    EXPECT_FALSE(orb::is_importer_extension("tri.obj"));
}

TEST(ImportScene, TheResultNamesItsImporter) {
    orb::ImportOptions options;
    options.allow_empty = true;
    EXPECT_EQ(orb::import_scene("camera 0 0 9 0 0 0\nsize 0\n", "s.scn", ".", options).format, "scn");
    options.format = "json";
    try {
        orb::import_scene("camera 0 0 9 0 0 0\nsize 0\n", "s.scn", ".", options);
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("s.scn:", 0), 0u) << e.what();  // the JSON reader's error
    }
}

TEST(ImportScene, AnUnknownFormatNamesTheKnownOnes) {
    orb::ImportOptions options;
    options.format = "obj";
    try {
        orb::import_scene("v 0 0 0\n", "tri.obj", ".", options);
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_STREQ(e.what(), "unknown scene format \"obj\"; the formats are scn, gltf, glb, ply, orb, json, orb-binary, pdb, ent, mmcif, cif, xyz, extxyz, lammps-dump, lammpstrj, gro");
    }
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
                                                 "); Orb reads .scn, .gltf/.glb, .ply, .json, .orb, .pdb/.ent, .cif/.mmcif, .xyz/.extxyz, .lammpstrj/.dump, .gro");
        }
    }
}

TEST(ImportScene, AChosenFormatIsReadAsChosen) {
    // --from scn: the .scn reader explains what it expected.
    orb::ImportOptions options;
    options.format = "scn";
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

TEST(ImportScene, AnExtensionThatDecidesPicksItsReader) {
    // An Orb JSON scene named .orb goes to the binary reader, whose error says what is wrong.
    const std::string json = R"({ "format": "orb-scene", "version": 1, "camera": { "position": [0,0,5], "target": [0,0,0] }, "materials": [], "spheres": [] })";
    try {
        orb::import_scene(json, "scene.ORB", ".");
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("scene.ORB: not an Orb binary scene", 0), 0u) << e.what();
    }
    orb::ImportOptions options;
    options.allow_empty = true;
    EXPECT_EQ(orb::import_scene(json, "scene.json", ".", options).format, "orb");
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
