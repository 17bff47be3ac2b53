// Devices, kernel building and the program binary cache.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "orb/kernels/embedded.h"
#include "render_test_support.h"

namespace orb::render::test {
namespace {

namespace fs = std::filesystem;

Scene tiny_scene()
{
    Scene scene;
    add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, MaterialType::Diffuse, {0.5, 0.5, 0.5}, {1, 1, 1}));
    scene.camera.position = {0, 0, 5};
    return scene;
}

// A fresh, empty cache directory for one test, used through XDG_CACHE_HOME.
class ScopedCacheHome {
public:
    ScopedCacheHome()
    {
        dir_ = fs::temp_directory_path() / ("orb-render-test-cache-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        const char* old = std::getenv("XDG_CACHE_HOME");
        had_old_ = old != nullptr;
        if (had_old_) old_ = old;
        ::setenv("XDG_CACHE_HOME", dir_.c_str(), 1);
    }
    ~ScopedCacheHome()
    {
        if (had_old_)
            ::setenv("XDG_CACHE_HOME", old_.c_str(), 1);
        else
            ::unsetenv("XDG_CACHE_HOME");
        std::error_code ec;
        fs::permissions(dir_, fs::perms::owner_all, ec);
        if (fs::exists(dir_ / "orb")) fs::permissions(dir_ / "orb", fs::perms::owner_all, ec);
        fs::remove_all(dir_, ec);
    }
    fs::path orb_dir() const { return dir_ / "orb"; }

private:
    fs::path dir_;
    bool had_old_ = false;
    std::string old_;
};

// Orb's cached binaries and any temporaries; PoCL keeps its own cache in the
// pocl/ folder beside them (docs/orb-render.md), which is not counted.
std::vector<fs::path> files_in(const fs::path& dir)
{
    std::vector<fs::path> out;
    if (fs::exists(dir))
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.is_regular_file()) out.push_back(entry.path());
    return out;
}

TEST(Devices, PoclCpuIsListedAndChosenByDefaultWithoutAGpu)
{
    const std::vector<DeviceInfo> devices = list_devices();
    ASSERT_FALSE(devices.empty());
    bool any_gpu = false;
    for (std::size_t i = 0; i < devices.size(); ++i) {
        EXPECT_EQ(devices[i].index, static_cast<int>(i));
        EXPECT_FALSE(devices[i].name.empty());
        EXPECT_GT(devices[i].compute_units, 0u);
        any_gpu |= devices[i].is_gpu;
    }
    const DeviceInfo chosen = choose_device("");
    EXPECT_EQ(chosen.is_gpu, any_gpu);
    EXPECT_EQ(choose_device("0").index, 0);
    EXPECT_EQ(choose_device(devices[0].name.substr(0, 4)).index, 0);
}

TEST(Devices, UnknownSelectorsNameTheChoices)
{
    try {
        choose_device("no-such-device-anywhere");
        FAIL() << "expected an error";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find(list_devices()[0].name), std::string::npos) << error.what();
    }
    EXPECT_THROW(choose_device("999"), std::runtime_error);
}

TEST(BinaryCache, SecondBuildLoadsTheCachedBinaryAndCorruptionIsNotFatal)
{
    ScopedCacheHome cache;
    const Film first = render(tiny_scene(), small_config(8, 8), {2});
    std::vector<fs::path> files = files_in(cache.orb_dir());
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files[0].extension(), ".bin");

    const Film cached = render(tiny_scene(), small_config(8, 8), {2});
    EXPECT_EQ(cached.radiance, first.radiance);

    // Truncate, then garble: each time the renderer rebuilds silently and rewrites the entry.
    fs::resize_file(files[0], fs::file_size(files[0]) / 2);
    EXPECT_EQ(render(tiny_scene(), small_config(8, 8), {2}).radiance, first.radiance);
    {
        std::fstream garble(files[0], std::ios::in | std::ios::out | std::ios::binary);
        garble.seekp(100);
        garble.write("garbage-garbage-garbage", 23);
    }
    EXPECT_EQ(render(tiny_scene(), small_config(8, 8), {2}).radiance, first.radiance);
    EXPECT_EQ(files_in(cache.orb_dir()).size(), 1u);  // no temporaries left behind
}

TEST(BinaryCache, UnwritableCacheIsIgnored)
{
    ScopedCacheHome cache;
    fs::create_directories(cache.orb_dir());
    fs::permissions(cache.orb_dir(), fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_NO_THROW(render(tiny_scene(), small_config(8, 8), {1}));
}

TEST(KernelBuild, FailureCarriesTheBuildLog)
{
    const fs::path dir = fs::temp_directory_path() / ("orb-broken-kernels-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    for (const kernels::EmbeddedKernel& k : kernels::embedded_kernels()) {
        const fs::path file = dir / std::string(k.file_name);
        fs::create_directories(file.parent_path());
        std::ofstream out(file);
        out << k.source;
        if (k.file_name == "integrator.cl") out << "\nthis_is_not_opencl_c;\n";
    }
    RenderConfig config = small_config(8, 8);
    config.kernel_dir = dir.string();
    config.use_binary_cache = false;
    try {
        Renderer renderer(tiny_scene(), config);
        FAIL() << "expected a build failure";
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("build log"), std::string::npos) << message;
        EXPECT_NE(message.find("integrator.cl:"), std::string::npos) << message;  // positions name the file
    }
    fs::remove_all(dir);
}

// GPUs build the kernels with one-sphere-at-a-time intersection; run that
// variant here on PoCL through the development knob ORB_CL_OPTIONS.
TEST(KernelBuild, GpuIntersectionVariantMatchesThePacketOne)
{
    const Scene cornell = load_scene_file(std::string(ORB_SCENES_DIR) + "/cornell.scn");
    const RenderConfig config = small_config(32, 24, 5);
    const Film packets = render(cornell, config, {16});
    const Film scalar = render_with_cl_options(cornell, config, {16}, "-DORB_SCALAR_TRAVERSAL=1 -DORB_DRAW_ALL_NUMBERS=1");
    EXPECT_EQ(scalar.object_id, packets.object_id);
    // Hit distances agree to the float precision of the radius-1e4 walls:
    // their centres sit 1e4 away, where one float ulp is about 1e-3.
    ASSERT_EQ(scalar.depth.size(), packets.depth.size());
    for (std::size_t i = 0; i < scalar.depth.size(); ++i) EXPECT_NEAR(scalar.depth[i], packets.depth[i], 4e-3) << i;
    // Same random numbers; float rounding may flip a rare roulette decision,
    // so compare the image means within 5 standard errors of their difference.
    for (int c = 0; c < 3; ++c) {
        const PixelStatistics a = radiance_statistics(packets, all_pixels(packets), c);
        const PixelStatistics b = radiance_statistics(scalar, all_pixels(scalar), c);
        EXPECT_NEAR(a.mean, b.mean, 5.0 * std::hypot(a.standard_error, b.standard_error)) << "channel " << c;
    }
}

TEST(Renderer, RejectsScenesTheKernelsCannotRender)
{
    Scene bad = tiny_scene();
    bad.spheres[0].material = 5;
    EXPECT_THROW(Renderer(bad, small_config(8, 8)), std::runtime_error);
    Scene flat = tiny_scene();
    flat.spheres[0].radius = 0;
    EXPECT_THROW(Renderer(flat, small_config(8, 8)), std::runtime_error);
    EXPECT_THROW(Renderer(tiny_scene(), small_config(0, 8)), std::invalid_argument);
}

TEST(Renderer, EmptySceneRendersBlack)
{
    Scene empty;
    const Film film = render(empty, small_config(8, 8), {2});
    for (float v : film.radiance) EXPECT_EQ(v, 0.0f);
    for (float id : film.object_id) EXPECT_EQ(id, -1.0f);
}

TEST(Renderer, SuggestedPassSizeStartsAtOneAndGrows)
{
    Renderer renderer(tiny_scene(), small_config(64, 64));
    EXPECT_EQ(renderer.suggested_samples_per_pass(), 1);
    for (int i = 0; i < 4; ++i) renderer.render_pass(renderer.suggested_samples_per_pass());
    EXPECT_GT(renderer.suggested_samples_per_pass(), 1);  // a 64x64 pass of one sample is far below 150 ms
    EXPECT_GT(renderer.device_memory_bytes(), 64u * 64u * 4u * 20u);
}

TEST(Renderer, BenchmarkReportsSamplesPerSecond)
{
    Renderer renderer(tiny_scene(), small_config(32, 32));
    const BenchmarkResult result = run_benchmark(renderer, 0.2);
    EXPECT_GT(result.passes, 0);
    EXPECT_GT(result.seconds, 0.0);
    EXPECT_EQ(result.samples % (32u * 32u), 0u);
    EXPECT_NEAR(result.samples_per_second, result.samples / result.seconds, 1e-6 * result.samples_per_second);
}

}  // namespace
}  // namespace orb::render::test
