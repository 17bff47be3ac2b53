// The embedding API: render_still on an in-memory scene gives the file
// orb-render writes for the same scene, seed and samples, bit for bit (the
// attributes that say when and where it ran aside); its layers are the
// file's; its callback and cancel flag stop it after a pass.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "exr_channels.h"
#include "job_test_support.h"
#include "orb/exr/film_exr.h"
#include "orb/import/import.h"
#include "orb/job/render_job.h"
#include "orb/scene/error.h"

namespace orb::job::test {
namespace {

std::string file_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

class RenderStill : public JobTest {
protected:
    // The scene as orb-render reads `scene.json`, in memory.
    Scene read_back(const std::string& file) {
        return import_scene(file_bytes(file), file, dir_, ImportOptions{}).scene;
    }
    // orb-render's file and render_still's image of the same render: their bytes, with the
    // image's time and device set to the file's (the only attributes that may differ).
    void expect_same_file(const std::vector<std::string>& options, const StillSettings& settings) {
        const std::string scene_file = write_scene(orb::test::small_scene());
        std::vector<std::string> args{scene_file, "-o", path("cli.exr"), "-q"};
        args.insert(args.end(), options.begin(), options.end());
        const orb::test::ProcessResult cli = render(args);
        ASSERT_EQ(cli.exit_code, 0) << cli.err;

        StillSettings still = settings;
        still.label = scene_file;  // orb:sceneFile: orb-render records the path
        RenderedImage image = render_still(read_back(scene_file), still);
        const exr::ExrMetadata file = exr::read_film_exr_header(path("cli.exr")).metadata;
        EXPECT_EQ(image.metadata.scene_hash, file.scene_hash);
        EXPECT_EQ(image.metadata.kernel, file.kernel);
        image.metadata.render_seconds = file.render_seconds;
        image.metadata.device = file.device;
        const std::string bytes = image.encode_exr();
        EXPECT_TRUE(bytes == file_bytes(path("cli.exr"))) << "render_still's EXR differs from orb-render's";

        image.save_exr(path("still.exr"));
        EXPECT_TRUE(file_bytes(path("still.exr")) == bytes);

        // Each layer as the file holds it.
        const exr::testing::RawExr raw = exr::testing::read_raw_exr(path("cli.exr"));
        const std::vector<Layer> layers = image.layers();
        ASSERT_FALSE(layers.empty());
        EXPECT_EQ(layers.front().name, "beauty");
        EXPECT_EQ(layers.front().channels, (std::vector<std::string>{"R", "G", "B", "A"}));
        for (const Layer& layer : layers) {
            ASSERT_EQ(layer.width, raw.width);
            ASSERT_EQ(layer.height, raw.height);
            for (std::size_t c = 0; c < layer.channels.size(); ++c) {
                const std::vector<float>& values = raw.channels.at(layer.channels[c]);
                for (std::size_t i = 0; i < values.size(); ++i)
                    ASSERT_EQ(layer.pixels[i * layer.channels.size() + c], values[i])
                        << layer.name << " " << layer.channels[c] << " pixel " << i;
            }
        }
    }
};

TEST_F(RenderStill, TheSameFileAsOrbRender) {
    StillSettings settings;
    settings.width = 12;
    settings.height = 8;
    settings.spp = 3;
    settings.seed = 9;
    expect_same_file({"--width", "12", "--height", "8", "--spp", "3", "--seed", "9"}, settings);
}

TEST_F(RenderStill, TheSameFileAsOrbRenderWithPassesAndTheScenesDefaults) {
    StillSettings settings;  // the scene's size (32x24) and spp (4), as orb-render without them
    settings.spp = 0;
    settings.passes = {exr::Pass::Beauty, exr::Pass::Albedo, exr::Pass::Normal, exr::Pass::Depth};
    settings.seed = 2;
    expect_same_file({"--passes", "beauty,albedo,normal,depth", "--seed", "2"}, settings);
}

TEST_F(RenderStill, TheCallbackStopsItAfterAPassAndSeesTheFilm) {
    StillSettings settings;
    settings.width = 8;
    settings.height = 6;
    settings.spp = 64;
    int calls = 0;
    std::uint64_t seen_spp = 0;
    const RenderedImage image = render_still(orb::test::small_scene(), settings,
                                             [&](const Progress& progress, const PreviewAccess& preview) {
                                                 ++calls;
                                                 seen_spp = preview.film().samples_per_pixel;
                                                 EXPECT_EQ(progress.target_spp, 64u);
                                                 return false;
                                             });
    EXPECT_EQ(calls, 1);
    EXPECT_TRUE(image.stopped);
    EXPECT_EQ(image.film.samples_per_pixel, seen_spp);
    EXPECT_LT(image.film.samples_per_pixel, 64u);
    EXPECT_EQ(image.metadata.scene_file, "<memory>");
    EXPECT_TRUE(image.options.exact_sums);  // stopped short: continuable bit for bit
}

TEST_F(RenderStill, SnapshotsComeBetweenPassesAndLeaveTheFinalImageAsItWas) {
    StillSettings settings;
    settings.width = 8;
    settings.height = 6;
    settings.spp = 64;
    const RenderedImage plain = render_still(orb::test::small_scene(), settings);
    std::vector<RenderedImage> snapshots;
    int passes = 0;
    settings.snapshot_passes = 1;
    settings.on_snapshot = [&](RenderedImage&& snapshot) { snapshots.push_back(std::move(snapshot)); };
    const RenderedImage image = render_still(orb::test::small_scene(), settings, [&](const Progress&, const PreviewAccess&) {
        ++passes;
        return true;
    });
    EXPECT_TRUE(image.layers().front().pixels == plain.layers().front().pixels) << "snapshots changed the final image";
    EXPECT_EQ(image.film.samples_per_pixel, 64u);
    EXPECT_FALSE(image.snapshot);
    // One after every pass but the last, whose image is the result.
    ASSERT_EQ(static_cast<int>(snapshots.size()), passes - 1);
    ASSERT_FALSE(snapshots.empty());
    EXPECT_EQ(snapshots.front().film.samples_per_pixel, 1u);  // the first pass is one sample
    for (std::size_t i = 0; i < snapshots.size(); ++i) {
        const RenderedImage& snapshot = snapshots[i];
        EXPECT_TRUE(snapshot.snapshot && !snapshot.stopped);
        EXPECT_EQ(snapshot.stats.spp, snapshot.film.samples_per_pixel);
        EXPECT_LT(snapshot.film.samples_per_pixel, 64u);
        if (i > 0) {
            EXPECT_GT(snapshot.film.samples_per_pixel, snapshots[i - 1].film.samples_per_pixel);
        }
        EXPECT_EQ(snapshot.layers().front().name, "beauty");
    }
}

TEST_F(RenderStill, ACancelFlagSetBeforehandStopsItBeforeAnyImage) {
    StillSettings settings;
    settings.width = 8;
    settings.height = 6;
    const std::atomic<bool> cancel{true};
    EXPECT_THROW(render_still(orb::test::small_scene(), settings, {}, &cancel), std::runtime_error);
}

TEST_F(RenderStill, RefusesABadSceneAsOrbRenderDoes) {
    Scene scene = orb::test::small_scene();
    scene.spheres[1].radius = -1;
    EXPECT_THROW(render_still(scene, StillSettings{}), orb::InputError);
}

TEST(ListDevices, SaysWhatOrbRenderListDevicesPrints) {
    const std::vector<DeviceListing> devices = list_devices();
    ASSERT_FALSE(devices.empty());  // the tests run on PoCL at least
    for (const DeviceListing& device : devices) {
        EXPECT_TRUE(device.type == "gpu" || device.type == "cpu" || device.type == "other") << device.type;
        EXPECT_FALSE(device.name.empty());
        EXPECT_GT(device.compute_units, 0u);
        EXPECT_EQ(device.version.rfind("OpenCL ", 0), 0u) << device.version;  // CL_DEVICE_VERSION's form
    }
}

}  // namespace
}  // namespace orb::job::test
