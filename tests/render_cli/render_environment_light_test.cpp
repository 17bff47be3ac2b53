// orb-render with an environment map: the map is found next to the scene,
// it is what escaping rays see (alpha 0), a bad map is one clear error with
// no output, its content is part of the scene hash that --resume checks,
// and a scene without any light is warned about.
#include <cmath>
#include <filesystem>
#include <fstream>

#include "cli_fixture.h"
#include "environment_exr_writer.h"
#include "orb/exr/film_exr.h"

using namespace orb::test;
using orb::exr::testing::MapFile;
using orb::exr::testing::read_raw_exr;
using orb::exr::testing::write_map_exr;

namespace {

// A map of one radiance everywhere.
MapFile constant_map(float r, float g, float b) {
    MapFile map;
    map.width = 4;
    map.height = 2;
    for (int i = 0; i < 8; ++i)
        for (float v : {r, g, b}) map.values.push_back(v);
    return map;
}

orb::Scene with_map(const std::string& map, double intensity) {
    orb::Scene scene = small_scene();
    scene.environment.kind = orb::EnvironmentKind::Map;
    scene.environment.map = map;
    scene.environment.intensity = intensity;
    return scene;
}

int error_lines(const std::string& err) {
    int lines = 0;
    for (std::size_t at = err.find("orb-render: error: "); at != std::string::npos;
         at = err.find("orb-render: error: ", at + 1))
        ++lines;
    return lines;
}

}  // namespace

TEST_F(RenderCli, AMapNextToTheSceneIsWhatEscapingRaysSee) {
    std::filesystem::create_directories(path("skies"));
    write_map_exr(path("skies/flat.exr"), constant_map(0.25f, 0.5f, 1.0f));
    const std::string scene = write_scene(with_map("skies/flat.exr", 2.0));
    const auto run = render({scene, "-o", path("out.exr"), "--spp", "2"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err;
    const auto image = read_raw_exr(path("out.exr"));
    // The top-left pixel is sky: the map's radiance times the intensity, exactly, with alpha 0.
    EXPECT_EQ(image.channels.at("R")[0], 0.5f);
    EXPECT_EQ(image.channels.at("G")[0], 1.0f);
    EXPECT_EQ(image.channels.at("B")[0], 2.0f);
    EXPECT_EQ(image.channels.at("A")[0], 0.0f);
}

TEST_F(RenderCli, BadMapsFailWithOneMessageAndNoOutput) {
    MapFile nan_map = constant_map(1, 1, 1);
    nan_map.values[3 * 5 + 1] = std::nanf("");
    write_map_exr(path("nan.exr"), nan_map);
    std::ofstream(path("text.exr")) << "not an EXR\n";
    const std::vector<std::pair<std::string, std::string>> cases{
        {"missing.exr", "scene.json: environment.map: " + path("missing.exr") + ": no such file"},
        {"nan.exr", "scene.json: environment.map: \"nan.exr\": texel (1, 1) channel G is NaN"},
        {"text.exr", "scene.json: environment.map: " + path("text.exr") + ": not an OpenEXR file"},
    };
    for (const auto& [map, message] : cases) {
        const std::string scene = write_scene(with_map(map, 1.0));
        const auto run = render({scene, "-o", path("out.exr")});
        EXPECT_EQ(run.exit_code, 1) << map;
        EXPECT_EQ(error_lines(run.err), 1) << run.err;
        EXPECT_NE(run.err.find(message), std::string::npos) << run.err;
        EXPECT_FALSE(std::filesystem::exists(path("out.exr"))) << map;
    }
}

TEST_F(RenderCli, ResumeRefusesAMapWhoseContentChanged) {
    write_map_exr(path("sky.exr"), constant_map(1, 1, 1));
    const std::string scene = write_scene(with_map("sky.exr", 1.0));
    ASSERT_EQ(render({scene, "-o", path("part.exr"), "--spp", "2"}).exit_code, 0);
    // The same file name with other texels is another scene.
    write_map_exr(path("sky.exr"), constant_map(1, 1, 2));
    const auto resumed = render({scene, "--resume", path("part.exr"), "-o", path("more.exr"), "--spp", "4"});
    EXPECT_EQ(resumed.exit_code, 1);
    EXPECT_NE(resumed.err.find("was rendered from a different scene"), std::string::npos) << resumed.err;
    EXPECT_FALSE(std::filesystem::exists(path("more.exr")));
    // Back to the original texels, it continues.
    write_map_exr(path("sky.exr"), constant_map(1, 1, 1));
    const auto again = render({scene, "--resume", path("part.exr"), "-o", path("more.exr"), "--spp", "4"});
    EXPECT_EQ(again.exit_code, 0) << again.err;
}

TEST_F(RenderCli, ASceneWithoutLightIsWarnedAbout) {
    orb::Scene dark = small_scene();
    dark.spheres.pop_back();  // the lamp
    const auto run = render({write_scene(dark), "-o", path("out.exr"), "--spp", "1"});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("orb-render: warning: " + path("scene.json") +
                           ": the scene has no light (no sphere emits and there is no environment); it renders black"),
              std::string::npos)
        << run.err;

    orb::Scene sky = dark;
    sky.environment.kind = orb::EnvironmentKind::Color;
    sky.environment.color = {1, 1, 1};
    const auto lit = render({write_scene(sky, "sky.json"), "-o", path("sky.exr"), "--spp", "1"});
    EXPECT_EQ(lit.exit_code, 0) << lit.err;
    EXPECT_EQ(lit.err.find("no light"), std::string::npos) << lit.err;
}
