// What orb-render writes: channels, attributes, their meaning, and options
// that shape the file.
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"
#include "orb/scene/scene_json.h"

using namespace orb::test;
using orb::exr::testing::read_raw_exr;

namespace {

std::set<std::string> channel_names(const orb::exr::testing::RawExr& raw) {
    std::set<std::string> names;
    for (const auto& [name, values] : raw.channels) names.insert(name);
    return names;
}

}  // namespace

TEST_F(RenderCli, WritesEveryDocumentedChannelAndAttribute) {
    const orb::Scene scene = small_scene();
    const std::string scene_file = write_scene(scene);
    const auto run = render({scene_file, "-o", path("out.exr"), "--seed", "7", "--passes", "all"});
    ASSERT_EQ(run.exit_code, 0) << run.err;

    const auto raw = read_raw_exr(path("out.exr"));
    EXPECT_EQ(raw.width, 32);
    EXPECT_EQ(raw.height, 24);
    EXPECT_EQ(channel_names(raw),
              (std::set<std::string>{"R",          "G",          "B",          "A",          "direct.R",
                                     "direct.G",   "direct.B",   "indirect.R", "indirect.G", "indirect.B",
                                     "emission.R", "emission.G", "emission.B", "albedo.R",   "albedo.G",
                                     "albedo.B",   "N.X",        "N.Y",        "N.Z",        "orb.normalLength",
                                     "Z",          "variance.R", "variance.G", "variance.B", "id",
                                     "background.R", "background.G", "background.B"}));
    for (const auto& [name, type] : raw.channel_types) EXPECT_EQ(type, "FLOAT") << name;

    const std::map<std::string, std::string> expected_attributes{
        {"orb:spp", "int"},          {"orb:targetSpp", "int"},         {"orb:seed", "string"},
        {"orb:sampleRanges", "string"},
        {"orb:maxDepth", "int"},     {"orb:mode", "string"},           {"orb:device", "string"},
        {"orb:renderSeconds", "double"}, {"orb:sceneFile", "string"},  {"orb:sceneHash", "string"},
        {"orb:sceneTime", "double"}, {"orb:version", "string"},        {"orb:passes", "string"},
        {"orb:filmFormat", "int"},   {"worldToCamera", "m44f"},        {"worldToNDC", "m44f"}};
    for (const auto& [name, type] : expected_attributes) {
        auto it = raw.attribute_types.find(name);
        ASSERT_NE(it, raw.attribute_types.end()) << name;
        EXPECT_EQ(it->second, type) << name;
    }

    Imf::InputFile file(path("out.exr").c_str());
    const Imf::Header& h = file.header();
    EXPECT_EQ(h.typedAttribute<Imf::IntAttribute>("orb:spp").value(), 4);  // the scene's render.spp
    EXPECT_EQ(h.typedAttribute<Imf::StringAttribute>("orb:seed").value(), "7");
    EXPECT_EQ(h.typedAttribute<Imf::IntAttribute>("orb:maxDepth").value(), 6);
    EXPECT_EQ(h.typedAttribute<Imf::StringAttribute>("orb:mode").value(), "global");
    EXPECT_FALSE(h.typedAttribute<Imf::StringAttribute>("orb:device").value().empty());
    EXPECT_GT(h.typedAttribute<Imf::DoubleAttribute>("orb:renderSeconds").value(), 0.0);
    EXPECT_EQ(h.typedAttribute<Imf::StringAttribute>("orb:sceneFile").value(), scene_file);
    EXPECT_EQ(h.typedAttribute<Imf::StringAttribute>("orb:sceneHash").value(), orb::scene_content_hash(scene));
    EXPECT_EQ(h.typedAttribute<Imf::StringAttribute>("orb:version").value(), ORB_VERSION);
}

TEST_F(RenderCli, TheDefaultIsTheBeautyLayerInFloatWithZip) {
    const auto run = render({write_scene(small_scene()), "-o", path("out.exr")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto raw = read_raw_exr(path("out.exr"));
    EXPECT_EQ(channel_names(raw), (std::set<std::string>{"R", "G", "B", "A"}));
    for (const auto& [name, type] : raw.channel_types) EXPECT_EQ(type, "FLOAT") << name;
    Imf::InputFile file(path("out.exr").c_str());
    EXPECT_EQ(file.header().compression(), Imf::ZIP_COMPRESSION);
    EXPECT_EQ(file.header().typedAttribute<Imf::StringAttribute>("orb:passes").value(), "beauty");
}

TEST_F(RenderCli, EveryCompressionStoresTheSameValues) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "-o", path("zip.exr"), "--passes", "all"}).exit_code, 0);
    const auto reference = read_raw_exr(path("zip.exr"));
    const std::map<std::string, Imf::Compression> kinds{
        {"none", Imf::NO_COMPRESSION}, {"rle", Imf::RLE_COMPRESSION}, {"zips", Imf::ZIPS_COMPRESSION},
        {"zip", Imf::ZIP_COMPRESSION}, {"piz", Imf::PIZ_COMPRESSION}};
    for (const auto& [name, kind] : kinds) {
        const std::string out = path(name + "-out.exr");
        const auto run = render({scene, "-o", out, "--passes", "all", "--compression", name});
        ASSERT_EQ(run.exit_code, 0) << name << ": " << run.err;
        Imf::InputFile file(out.c_str());
        EXPECT_EQ(file.header().compression(), kind) << name;
        // Lossless: the same seed gives the same image, bit for bit, however it is stored.
        EXPECT_EQ(read_raw_exr(out).channels, reference.channels) << name;
    }
    const auto bad = render({scene, "-o", path("bad.exr"), "--compression", "dwaa"});
    EXPECT_EQ(bad.exit_code, 2) << bad.err;
    EXPECT_NE(bad.err.find("--compression"), std::string::npos) << bad.err;
}

TEST_F(RenderCli, PartsAddUpToBeautyAndAuxiliaryChannelsHaveTheirMeaning) {
    const orb::Scene scene = small_scene();
    const auto run = render({write_scene(scene), "-o", path("out.exr"), "--spp", "6", "--passes", "all"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto raw = read_raw_exr(path("out.exr"));
    const auto& ch = raw.channels;

    int hits = 0, misses = 0;
    for (std::size_t i = 0; i < ch.at("R").size(); ++i) {
        for (const char* c : {"R", "G", "B"}) {
            const std::string s = c;
            const double parts = double(ch.at("direct." + s)[i]) + ch.at("indirect." + s)[i] + ch.at("emission." + s)[i];
            // Four float sums rounded to means: a few ulps of the largest.
            EXPECT_NEAR(ch.at(s)[i], parts, 1e-5 * std::max(1.0, parts)) << s << " pixel " << i;
            EXPECT_GE(ch.at("variance." + s)[i], 0.0f);
        }
        const float id = ch.at("id")[i], z = ch.at("Z")[i];
        const double nx = ch.at("N.X")[i], ny = ch.at("N.Y")[i], nz = ch.at("N.Z")[i];
        const double length = std::sqrt(nx * nx + ny * ny + nz * nz);
        if (id < 0) {
            ++misses;
            EXPECT_EQ(id, -1.0f);
            EXPECT_TRUE(std::isinf(z) && z > 0) << "pixel " << i << " Z " << z;
        } else {
            ++hits;
            EXPECT_EQ(id, std::floor(id));
            EXPECT_LT(id, float(scene.spheres.size()));
            EXPECT_TRUE(std::isfinite(z) && z > 0) << "pixel " << i;
        }
        EXPECT_TRUE(length == 0.0 || std::fabs(length - 1.0) < 1e-5) << "pixel " << i << " |N| " << length;
        EXPECT_GE(ch.at("A")[i], 0.0f);
        EXPECT_LE(ch.at("A")[i], 1.0f);
    }
    EXPECT_GT(hits, 0);
    EXPECT_GT(misses, 0);  // the sky at the top
}

TEST_F(RenderCli, WorldToNdcPutsEachSphereCentreOnThatSpheresPixels) {
    const orb::Scene scene = small_scene();
    ASSERT_EQ(render({write_scene(scene), "-o", path("out.exr"), "--spp", "1", "--passes", "id"}).exit_code, 0);
    Imf::InputFile file(path("out.exr").c_str());
    const Imath::M44f to_ndc = Imf::worldToNDC(file.header());
    const Imath::M44f to_camera = Imf::worldToCamera(file.header());
    const auto raw = read_raw_exr(path("out.exr"));
    for (std::size_t s = 1; s < scene.spheres.size(); ++s) {  // the floor's centre is far below
        const auto& c = scene.spheres[s].center;
        const Imath::V3f centre{static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
        Imath::V3f ndc, cam;
        to_ndc.multVecMatrix(centre, ndc);
        to_camera.multVecMatrix(centre, cam);
        EXPECT_GT(cam.z, 0) << "sphere " << s << " is in front of the camera";
        const int x = int(ndc.x * raw.width), y = int(ndc.y * raw.height);
        ASSERT_TRUE(x >= 0 && x < raw.width && y >= 0 && y < raw.height) << s << ": " << ndc.x << "," << ndc.y;
        EXPECT_EQ(raw.channels.at("id")[std::size_t(y) * raw.width + x], float(s)) << "sphere " << s;
    }
}

TEST_F(RenderCli, SameSeedGivesIdenticalPixelsAndAnotherSeedDoesNot) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "-o", path("a.exr"), "--seed", "3"}).exit_code, 0);
    ASSERT_EQ(render({scene, "-o", path("b.exr"), "--seed", "3"}).exit_code, 0);
    ASSERT_EQ(render({scene, "-o", path("c.exr"), "--seed", "4"}).exit_code, 0);
    const auto a = read_raw_exr(path("a.exr")), b = read_raw_exr(path("b.exr")), c = read_raw_exr(path("c.exr"));
    EXPECT_EQ(a.channels, b.channels);
    EXPECT_NE(a.channels.at("R"), c.channels.at("R"));
}

TEST_F(RenderCli, HalfKeepsDepthAndIdAsFloat) {
    ASSERT_EQ(render({write_scene(small_scene()), "-o", path("half.exr"), "--half"}).exit_code, 0);
    const auto raw = read_raw_exr(path("half.exr"));
    for (const auto& [name, type] : raw.channel_types) {
        const bool stays_float = name == "Z" || name == "id" || name == "orb.normalLength";
        EXPECT_EQ(type, stays_float ? "FLOAT" : "HALF") << name;
    }
}

TEST_F(RenderCli, PassesPicksTheLayers) {
    ASSERT_EQ(render({write_scene(small_scene()), "-o", path("out.exr"), "--passes", "depth,beauty"}).exit_code, 0);
    EXPECT_EQ(channel_names(read_raw_exr(path("out.exr"))), (std::set<std::string>{"A", "B", "G", "R", "Z"}));
}

TEST_F(RenderCli, HeaderRecordsModeDepthAndSize) {
    const auto run = render({write_scene(small_scene()), "-o", path("out.exr"), "--mode", "direct", "--max-depth",
                             "3", "--width", "20", "--height", "10", "--spp", "2"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto film = orb::exr::read_film_exr(path("out.exr"));
    EXPECT_EQ(film.metadata.mode, "direct");
    EXPECT_EQ(film.metadata.max_depth, 3);
    EXPECT_EQ(film.film.width, 20);
    EXPECT_EQ(film.film.height, 10);
    EXPECT_EQ(film.film.samples_per_pixel, 2u);
}

TEST_F(RenderCli, StdoutStreamsAValidExr) {
    const std::string scene = write_scene(small_scene());
    const auto run = render({scene, "-o", "-", "--spp", "2"}, "", path("streamed.exr"));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto film = orb::exr::read_film_exr(path("streamed.exr"));
    EXPECT_EQ(film.film.samples_per_pixel, 2u);
    EXPECT_EQ(film.film.width, 32);
}

TEST_F(RenderCli, SceneFromStdin) {
    const orb::Scene scene = small_scene();
    const auto run = render({"-", "-o", path("out.exr"), "--spp", "1"}, write_scene(scene));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto film = orb::exr::read_film_exr(path("out.exr"));
    EXPECT_EQ(film.metadata.scene_file, "<stdin>");
    EXPECT_EQ(film.metadata.scene_hash, orb::scene_content_hash(scene));
}

TEST_F(RenderCli, StatsJsonHasTheRunsFigures) {
    const auto run = render({write_scene(small_scene()), "-o", path("out.exr"), "--spp", "3", "--stats-json",
                             path("stats.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto stats = nlohmann::json::parse(read_text(path("stats.json")));
    EXPECT_FALSE(stats.at("device").at("name").get<std::string>().empty());
    EXPECT_EQ(stats.at("spp").get<int>(), 3);
    EXPECT_EQ(stats.at("width").get<int>(), 32);
    EXPECT_GT(stats.at("seconds").get<double>(), 0.0);
    EXPECT_GT(stats.at("samples_per_second").get<double>(), 0.0);
    EXPECT_GT(stats.at("device_memory_bytes").get<std::uint64_t>(), 0u);
    EXPECT_EQ(stats.at("stop_reason").get<std::string>(), "spp");
    // Four spheres: no tree. Getting ready (reading, kernels, upload) is not
    // part of the rendering seconds.
    EXPECT_EQ(stats.at("bvh_nodes").get<std::size_t>(), 0u);
    EXPECT_GT(stats.at("setup_seconds").get<double>(), 0.0);
}

// A scene with a tree says how big it is and how long getting ready took,
// on stderr and in --stats-json, with the same node count in both.
TEST_F(RenderCli, ReportsTheTreeAndTheTimeBeforeTheFirstPass) {
    orb::Scene scene = small_scene();
    for (int i = 0; i < 300; ++i)
        scene.spheres.push_back({"", {-2.0 + 0.013 * i, 0.2 + 0.005 * i, -1.0 - 0.004 * i}, 0.05, 0});
    const auto run = render({write_scene(scene), "-o", path("out.exr"), "--spp", "1", "--stats-json", path("stats.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto stats = nlohmann::json::parse(read_text(path("stats.json")));
    const auto nodes = stats.at("bvh_nodes").get<std::size_t>();
    EXPECT_GT(nodes, 0u);
    EXPECT_GE(stats.at("bvh_seconds").get<double>(), 0.0);
    EXPECT_GE(stats.at("setup_seconds").get<double>(), stats.at("bvh_seconds").get<double>());
    EXPECT_NE(run.err.find("ready in "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("BVH of " + std::to_string(nodes) + " nodes over 304 spheres built in "), std::string::npos)
        << run.err;
}

TEST_F(RenderCli, PrintsTheDeviceAndQuietSilencesEverything) {
    const std::string scene = write_scene(small_scene());
    const auto loud = render({scene, "-o", path("a.exr"), "--spp", "1"});
    ASSERT_EQ(loud.exit_code, 0) << loud.err;
    EXPECT_NE(loud.err.find("device: "), std::string::npos) << loud.err;
    EXPECT_NE(loud.err.find("ready in "), std::string::npos) << loud.err;
    EXPECT_NE(loud.err.find("4 spheres, no BVH"), std::string::npos) << loud.err;
    const auto quiet = render({scene, "-o", path("b.exr"), "--spp", "1", "-q"});
    ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
    EXPECT_EQ(quiet.err, "");
}
