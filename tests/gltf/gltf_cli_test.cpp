// orb-import's glTF flags and its behaviour on the whole validator corpus:
// exit 0 with a scene, or exit 1 with one "orb-import: error:" message and
// no output file; usage mistakes exit 2.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "gltf_test_util.h"
#include "orb/scene/animation.h"
#include "orb/scene/scene_json.h"

namespace orb::gltf_test {
namespace {

namespace fs = std::filesystem;

struct ToolRun {
    int status = -1;
    std::string out, err;
};

std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

ToolRun run_import(const std::string& args, const fs::path& output) {
    const fs::path dir = fs::temp_directory_path() / ("orb_gltf_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path err = dir / "stderr.txt";
    const std::string command = quote(ORB_IMPORT_EXE) + " " + args + " -o " + quote(output.string()) + " 2> " +
                                quote(err.string()) + " < /dev/null";
    const int raw = std::system(command.c_str());
    ToolRun run;
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
    run.err = read_file(err.string());
    if (fs::exists(output)) run.out = read_file(output.string());
    return run;
}

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("orb_gltf_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::remove(dir / name);
    return dir / name;
}

TEST(GltfCli, FlagsReachTheImporter) {
    const fs::path out = scratch("out.json");
    ToolRun run = run_import(quote(generated("scenes.gltf")) + " --gltf-scene two", out);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(load_scene_json(run.out, "out").spheres.at(0).name, "Second");
    run = run_import(quote(generated("scenes.gltf")) + " --scene two", out);  // the older name, kept for scripts
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(load_scene_json(run.out, "out").spheres.at(0).name, "Second");

    run = run_import(quote(generated("cameras.glb")) + " --camera Side", out);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(load_scene_json(run.out, "out").camera.position, (Vec3{10, 0, 0}));

    run = run_import(quote(generated("non_sphere.gltf")) + " --non-spheres bound --no-default-light", out);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(load_scene_json(run.out, "out").spheres.size(), 2u);

    run = run_import(quote(generated("non_sphere.gltf")), out);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.err.find("warning"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("'Cube'"), std::string::npos) << run.err;

    run = run_import(quote(generated("point_light.gltf")) + " --light-radius 0.25", out);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(sphere_named(load_scene_json(run.out, "out"), "Bulb").radius, 0.25);

    for (const char* units : {"radiometric", "photometric"}) {
        run = run_import(quote(generated("point_light.gltf")) + " --light-radius 0.25 --light-units " + units, out);
        ASSERT_EQ(run.status, 0) << run.err;
        const Scene scene = load_scene_json(run.out, "out");
        const double radiant = std::string(units) == "radiometric" ? 100.0 : 100.0 / 683;
        EXPECT_NEAR(scene.materials.at(sphere_named(scene, "Bulb").material).emission[0],
                    radiant / (std::numbers::pi * 0.0625), 1e-9 * radiant)
            << units;
    }

    run = run_import(quote(generated("points.gltf")) + " --point-radius 0.3", out);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(sphere_named(load_scene_json(run.out, "out"), "Plain.point0").radius, 0.3);

    run = run_import(quote(generated("all_lights.gltf")) + " --directional-lights", out);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_NO_THROW(sphere_named(load_scene_json(run.out, "out"), "Sun"));
    EXPECT_LT(load_scene_json(run.out, "out").camera.position[2], 100.0) << "framed the scene, not the sun";

    run = run_import(quote(generated("nested.gltf")) + " --sphere-tolerance 0.01 --no-default-light", out);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(load_scene_json(run.out, "out").spheres.size(), 3u);

    run = run_import(quote(generated("clips.glb")) + " --animation Slide --strict", out);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(scene_at_time(load_scene_json(run.out, "out"), 1.0).spheres.at(0).center[0], 2.0);
    run = run_import(quote(generated("clips.glb")) + " --animation 7", out);
    EXPECT_EQ(run.status, 1) << run.err;
    EXPECT_NE(run.err.find("--animation 7: no such animation"), std::string::npos) << run.err;

    run = run_import(quote(generated("animation.glb")), out);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_FALSE(load_scene_json(run.out, "out").animation.empty());
}

// The default light is warned about (never fatal: --strict passes), and
// --no-default-light turns it off.
TEST(GltfCli, DefaultLightAndNoDefaultLight) {
    const fs::path out = scratch("light.json");
    ToolRun run = run_import(quote(generated("nested.glb")) + " --strict", out);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.err.find("orb-import: warning: " + generated("nested.glb") + ": the asset has no light"),
              std::string::npos)
        << run.err;
    EXPECT_EQ(load_scene_json(run.out, "out").environment.kind, EnvironmentKind::Color);

    run = run_import(quote(generated("nested.glb")) + " --no-default-light", out);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.err.find("no light"), std::string::npos) << run.err;
    EXPECT_EQ(load_scene_json(run.out, "out").environment.kind, EnvironmentKind::None);
}

// A chosen environment lights the asset: no default light and no warning about one.
TEST(GltfCli, AChosenEnvironmentReplacesTheDefaultLight) {
    const fs::path out = scratch("environment.json");
    const ToolRun run = run_import(quote(generated("nested.glb")) + " --environment 0.25,0.5,1 --strict", out);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.err.find("no light"), std::string::npos) << run.err;
    const Environment environment = load_scene_json(run.out, "out").environment;
    EXPECT_EQ(environment.kind, EnvironmentKind::Color);
    EXPECT_EQ(environment.color, (Vec3{0.25, 0.5, 1}));
}

TEST(GltfCli, ErrorsAndUsage) {
    const fs::path out = scratch("bad.json");
    ToolRun run = run_import(quote(generated("ortho.gltf")) + " --camera Mirrored", out);
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.err.find("orb-import: error:"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("orthographic ymag -1 must be > 0"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));

    run = run_import(quote(generated("non_sphere.gltf")) + " --non-spheres error", out);
    EXPECT_EQ(run.status, 1) << run.err;
    EXPECT_FALSE(fs::exists(out));

    run = run_import(quote(generated("non_uniform.gltf")) + " --strict", out);
    EXPECT_EQ(run.status, 1) << run.err;

    // Everything dropped, in one warning naming the file; --strict refuses it.
    run = run_import(quote(generated("ignored.glb")), out);
    EXPECT_EQ(run.status, 0) << run.err;
    // orb-import reads base-colour textures (these spheres have no TEXCOORD_0 for them: a warning each).
    EXPECT_NE(run.err.find(generated("ignored.glb") + ": ignored: 1 normal texture"), std::string::npos)
        << run.err;
    fs::remove(out);
    run = run_import(quote(generated("ignored.glb")) + " --strict", out);
    EXPECT_EQ(run.status, 1) << run.err;
    // The first loss stops it: the base-colour texture that has no TEXCOORD_0 to be read through.
    EXPECT_NE(run.err.find("orb-import: error: " + generated("ignored.glb") + ": material 'Velvet' base-colour "
                           "texture: the mesh has no TEXCOORD_0"),
              std::string::npos)
        << run.err;
    EXPECT_FALSE(fs::exists(out));

    run = run_import(quote(generated("draco.glb")), out);
    EXPECT_EQ(run.status, 1) << run.err;
    EXPECT_EQ(run.err, "orb-import: error: " + generated("draco.glb") +
                           ": extensionsRequired[0]: the asset requires KHR_draco_mesh_compression, which Orb cannot "
                           "decode\n");
    EXPECT_FALSE(fs::exists(out));

    run = run_import(quote(generated("nested.gltf")) + " --non-spheres maybe", out);
    EXPECT_EQ(run.status, 2) << run.err;
    run = run_import(quote(generated("nested.gltf")) + " --sphere-tolerance -1", out);
    EXPECT_EQ(run.status, 2) << run.err;
    run = run_import(quote(generated("nested.gltf")) + " --light-units lumens", out);
    EXPECT_EQ(run.status, 2) << run.err;
}

// Bytes that are not text, quoted by the JSON parser in its message, come
// out escaped (\xFF): the message stays valid UTF-8 on any terminal.
TEST(GltfCli, RandomBytesAreQuotedEscaped) {
    const fs::path input = scratch("random.gltf");
    std::ofstream(input, std::ios::binary) << std::string("{\"asset\": \xff\xfe\x01}", 14);
    const fs::path out = scratch("random.json");
    const ToolRun run = run_import(quote(input.string()), out);
    EXPECT_EQ(run.status, 1) << run.err;
    EXPECT_NE(run.err.find("not a valid glTF 2.0 asset"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("\\xFF"), std::string::npos) << run.err;
    for (char c : run.err) {
        const auto byte = static_cast<unsigned char>(c);
        EXPECT_TRUE(byte == '\n' || (byte >= 0x20 && byte < 0x7f)) << "byte " << int(byte) << " in: " << run.err;
    }
    EXPECT_FALSE(fs::exists(out));
}

TEST(GltfCli, WholeValidatorCorpus) {
    ASSERT_TRUE(fs::is_directory(ORB_GLTF_CORPUS_DIR)) << "missing corpus " << ORB_GLTF_CORPUS_DIR;
    std::size_t files = 0, ok = 0, refused = 0;
    const fs::path out = scratch("corpus.json");
    for (const auto& entry : fs::recursive_directory_iterator(ORB_GLTF_CORPUS_DIR)) {
        const std::string ext = entry.path().extension().string();
        if (!entry.is_regular_file() || (ext != ".gltf" && ext != ".glb")) continue;
        ++files;
        fs::remove(out);
        const ToolRun run = run_import(quote(entry.path().string()), out);
        if (run.status == 0) {
            ++ok;
            EXPECT_NO_THROW(load_scene_json(run.out, entry.path().string()));
        } else {
            ++refused;
            EXPECT_EQ(run.status, 1) << entry.path() << "\n" << run.err;
            EXPECT_NE(run.err.find("orb-import: error: " + entry.path().string() + ": "), std::string::npos)
                << run.err;
            EXPECT_FALSE(fs::exists(out)) << entry.path() << ": partial output left behind";
        }
    }
    EXPECT_EQ(files, 372u);
    EXPECT_EQ(ok + refused, files);
}

// orb-import decodes textures through the module it loads from
// ../lib/orb beside its own folder (the tools do not link OpenImageIO); a
// copy of the tool without that module imports the factors alone and says
// why, and --strict refuses.
TEST(GltfCli, TexturesAreReadThroughTheLoadedDecoderAndItsAbsenceIsNamed) {
    const fs::path out = scratch("textured.json");
    ToolRun run = run_import(quote(generated("textures.glb")), out);
    ASSERT_EQ(run.status, 0) << run.err;
    const Scene scene = load_scene_json(run.out, "textured");
    const Sphere& a0 = sphere_named(scene, "A.0");
    EXPECT_NEAR(scene.materials[a0.material].roughness, 102.0 / 255.0, 1e-6) << "the atlas cell, not the factor 1";

    const fs::path bin = scratch("lonely") / "bin";
    fs::create_directories(bin);
    fs::copy_file(ORB_IMPORT_EXE, bin / "orb-import", fs::copy_options::overwrite_existing);
    const fs::path err = scratch("lonely.err");
    const std::string command = quote((bin / "orb-import").string()) + " " + quote(generated("textures.glb")) + " -o " +
                                quote(out.string()) + " 2> " + quote(err.string());
    int raw = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << read_file(err.string());
    const std::string message = read_file(err.string());
    EXPECT_NE(message.find("textures cannot be decoded here: the texture decoder (OpenImageIO) did not load ("),
              std::string::npos) << message;
    EXPECT_NE(message.find("lib/orb/orb_texture_decoder.so"), std::string::npos) << message;
    EXPECT_EQ(sphere_named(load_scene_json(read_file(out.string()), "factors"), "A.0").name, "A.0");

    fs::remove(out);
    raw = std::system((command + " --strict").c_str());
    EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 1) << read_file(err.string());
    EXPECT_FALSE(fs::exists(out));
    fs::remove_all(bin.parent_path());
}

}  // namespace
}  // namespace orb::gltf_test
