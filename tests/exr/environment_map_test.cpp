// Environment maps read from EXR (orb/exr/environment_map.h): what is read,
// how relative paths resolve, and the message for every kind of bad map.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "environment_exr_writer.h"
#include "orb/exr/environment_map.h"
#include "orb/scene/error.h"
#include "test_film.h"

using namespace orb::exr;
using orb::exr::testing::MapFile;
using orb::exr::testing::gradient_map;
using orb::exr::testing::scratch_path;
using orb::exr::testing::message_of;
using orb::exr::testing::write_map_exr;

namespace {

namespace fs = std::filesystem;

orb::Scene scene_with_map(const std::string& map, double intensity = 1.0) {
    orb::Scene s;
    s.camera.position = {0, 0, 5};
    s.environment.kind = orb::EnvironmentKind::Map;
    s.environment.map = map;
    s.environment.intensity = intensity;
    return s;
}

TEST(EnvironmentMap, ReadsRgbRowsFromTheTop) {
    const std::string path = scratch_path("sky.exr");
    write_map_exr(path, gradient_map(5, 3, 0.25f));
    const orb::EnvironmentImage image = read_environment_exr(path);
    ASSERT_EQ(image.width, 5);
    ASSERT_EQ(image.height, 3);
    ASSERT_EQ(image.rgb.size(), 45u);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) {
            const std::size_t i = 3 * std::size_t(y * 5 + x);
            EXPECT_EQ(image.rgb[i], 0.25f * x);
            EXPECT_EQ(image.rgb[i + 1], 0.25f * y);
            EXPECT_EQ(image.rgb[i + 2], 0.125f);
        }
}

TEST(EnvironmentMap, ReadsHalfAnOffsetDataWindowAndIgnoresAlpha) {
    MapFile map;
    map.width = 3;
    map.height = 2;
    map.channels = {"A", "B", "G", "R"};
    map.half = true;
    map.origin_x = -7;
    map.origin_y = 11;
    for (int i = 0; i < 6; ++i)
        for (float v : {1.0f, 0.5f * i, 0.25f * i, 70000.0f * (i == 5)}) map.values.push_back(v);  // A, B, G, R
    const std::string path = scratch_path("half.exr");
    write_map_exr(path, map);
    const orb::EnvironmentImage image = read_environment_exr(path);
    ASSERT_EQ(image.width, 3);
    ASSERT_EQ(image.height, 2);
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(image.rgb[3 * std::size_t(i)], i == 5 ? INFINITY : 0.0f) << i;  // 70000 overflows HALF
        EXPECT_EQ(image.rgb[3 * std::size_t(i) + 1], 0.25f * i);
        EXPECT_EQ(image.rgb[3 * std::size_t(i) + 2], 0.5f * i);
    }
}

TEST(EnvironmentMap, ReadsLuminanceAsGrey) {
    MapFile map;
    map.width = 2;
    map.height = 1;
    map.channels = {"Y"};
    map.values = {0.5f, 3.0f};
    const std::string path = scratch_path("grey.exr");
    write_map_exr(path, map);
    EXPECT_EQ(read_environment_exr(path).rgb, (std::vector<float>{0.5f, 0.5f, 0.5f, 3.0f, 3.0f, 3.0f}));
}

TEST(EnvironmentMap, RefusesWhatIsNotALatLongColourMap) {
    const std::string missing = scratch_path("missing.exr");
    EXPECT_EQ(message_of([&] { read_environment_exr(missing); }), missing + ": no such file");

    const std::string folder = scratch_path("folder.exr");
    fs::create_directories(folder);
    EXPECT_EQ(message_of([&] { read_environment_exr(folder); }), folder + ": is a directory, expected an OpenEXR file");

    const std::string text = scratch_path("sky.exr.txt");
    std::ofstream(text) << "not an image\n";
    EXPECT_EQ(message_of([&] { read_environment_exr(text); }),
              text + ": not an OpenEXR file (environment maps are read as EXR)");

    MapFile depth;
    depth.width = depth.height = 2;
    depth.channels = {"Z"};
    depth.values = {1, 2, 3, 4};
    const std::string z = scratch_path("depth.exr");
    write_map_exr(z, depth);
    EXPECT_EQ(message_of([&] { read_environment_exr(z); }),
              z + ": has no R, G, B (or Y) channels to read as radiance (it has: Z)");

    MapFile cube = gradient_map(4, 24);
    cube.cube_map = true;
    const std::string c = scratch_path("cube.exr");
    write_map_exr(c, cube);
    EXPECT_EQ(message_of([&] { read_environment_exr(c); }),
              c + ": is a cube map (envmap attribute); Orb reads latitude-longitude maps");

    // A file cut short.
    const std::string whole = scratch_path("whole.exr"), cut = scratch_path("cut.exr");
    write_map_exr(whole, gradient_map(64, 32));
    std::ifstream in(whole, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    const std::string message = message_of([&] { read_environment_exr(cut); });
    EXPECT_EQ(message.rfind(cut + ": ", 0), 0u) << message;
    EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

TEST(EnvironmentMap, ResolvesRelativePathsAgainstTheScenesFolder) {
    const fs::path folder = fs::path(scratch_path("scene")) / "maps";
    fs::create_directories(folder);
    write_map_exr((folder / "sky.exr").string(), gradient_map(4, 2));

    orb::Scene relative = scene_with_map("maps/sky.exr");
    load_environment_map(relative, folder.parent_path().string(), "s.json");
    ASSERT_NE(relative.environment.image, nullptr);
    EXPECT_EQ(relative.environment.image->width, 4);
    EXPECT_EQ(relative.environment.map, "maps/sky.exr");  // the scene still says what it said

    orb::Scene absolute = scene_with_map((folder / "sky.exr").string());
    load_environment_map(absolute, "/nonexistent", "s.json");
    EXPECT_EQ(*absolute.environment.image, *relative.environment.image);

    orb::Scene colour;
    colour.environment.kind = orb::EnvironmentKind::Color;
    load_environment_map(colour, "/nonexistent", "s.json");
    EXPECT_EQ(colour.environment.image, nullptr);
}

TEST(EnvironmentMap, BadMapsAreReportedWithTheSceneAndTheJsonPath) {
    const std::string folder = fs::path(scratch_path("sky.exr")).parent_path().string();
    orb::Scene missing = scene_with_map("nope.exr");
    EXPECT_EQ(message_of([&] { load_environment_map(missing, folder, "s.json"); }),
              "s.json: environment.map: " + (fs::path(folder) / "nope.exr").string() + ": no such file");

    const auto with_texel = [&](float value, double intensity) {
        MapFile map = gradient_map(4, 2);
        map.values[3 * (1 * 4 + 3) + 2] = value;  // texel (3, 1), B
        write_map_exr(scratch_path("bad.exr"), map);
        orb::Scene s = scene_with_map("bad.exr", intensity);
        return message_of([&] { load_environment_map(s, folder, "s.json"); });
    };
    EXPECT_EQ(with_texel(NAN, 1), "s.json: environment.map: \"bad.exr\": texel (3, 1) channel B is NaN; an environment map holds finite radiance >= 0");
    EXPECT_EQ(with_texel(-1, 1), "s.json: environment.map: \"bad.exr\": texel (3, 1) channel B is negative (-1); radiance is >= 0");
    EXPECT_EQ(with_texel(INFINITY, 1), "s.json: environment.map: \"bad.exr\": texel (3, 1) channel B is infinite; an environment map holds finite radiance >= 0");
    EXPECT_NE(with_texel(1e9f, 1e4).find("texel (3, 1) channel B is 1000000000, times intensity 10000 above 1000000000000"),
              std::string::npos);
    EXPECT_EQ(with_texel(1e9f, 1), "(no orb::InputError thrown)");
}

}  // namespace
