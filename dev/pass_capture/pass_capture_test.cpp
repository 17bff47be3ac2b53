// The pass capture writes one pass to a folder for a replay outside OpenCL
// (dev/pass_capture/pass_capture.h; cuda_replay.cpp beside it replays it
// through CUDA for Nsight Compute). A replay is only worth its profile if
// the capture is exactly the pass: every kernel argument in order with its
// bytes, the film before it and the film after it.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "orb/tables/device_types.h"
#include "pass_arguments.h"
#include "pass_capture.h"
#include "program_build.h"
#include "render_test_support.h"

using namespace orb;
using namespace orb::render;
using namespace orb::render::test;

namespace {

std::vector<char> read_bytes(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    EXPECT_TRUE(in) << path;
    return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

// A film channel's storage, sums or values, as bytes.
std::vector<char> bytes_of(const Film& film, film::Channel channel)
{
    const std::span<const std::byte> stored = film.bytes(channel);
    std::vector<char> bytes(stored.size());
    if (!bytes.empty()) std::memcpy(bytes.data(), stored.data(), bytes.size());
    return bytes;
}

struct CapturedArg {
    int index = -1;
    std::string kind;
    std::size_t bytes = 0;
    std::string file;
};

class CaptureDir {
public:
    CaptureDir()
        : path_(std::filesystem::temp_directory_path() /
                ("orb-capture-test-" + std::to_string(::getpid()) + "-" + std::to_string(next_++)))
    {
        std::filesystem::remove_all(path_);
    }
    ~CaptureDir() { std::filesystem::remove_all(path_); }
    const std::filesystem::path& path() const { return path_; }

private:
    static inline int next_ = 0;  // two folders of one test never meet
    std::filesystem::path path_;
};

}  // namespace

TEST(PassCapture, WritesTheSecondPassExactlyAsTheRendererRanIt)
{
    Scene scene;
    scene.camera.position = {0.0, 1.0, 4.0};
    scene.camera.target = {0.0, 1.0, 0.0};
    add_sphere(scene, {0.0, 0.0, 0.0}, 50.0, add_material(scene, MaterialType::Diffuse, {0.7, 0.7, 0.7}));
    add_sphere(scene, {0.0, 4.0, 0.0}, 0.8, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {8, 8, 8}));
    add_sphere(scene, {0.5, 0.6, 0.0}, 0.5, add_material(scene, MaterialType::Dielectric, {1, 1, 1}));
    const RenderConfig config = small_config(24, 16, 11);

    // The first pass writes the centre rays and is never captured; the
    // second (2 samples, from sample 1 on) is.
    const CaptureDir dir;
    RenderConfig capturing = config;
    const auto capture = std::make_shared<PassCapture>(dir.path().string(), 0);
    capturing.development.pass_observer = capture;
    test::render(scene, capturing, {1, 2, 3});
    EXPECT_TRUE(capture->taken());
    const Film before = test::render(scene, config, {1});
    const Film after = test::render(scene, config, {1, 2});

    std::ifstream launch(dir.path() / "launch.txt");
    ASSERT_TRUE(launch) << "no launch.txt in " << dir.path();
    std::vector<CapturedArg> args;
    std::string line, kernel, options;
    while (std::getline(launch, line)) {
        std::istringstream words(line);
        std::string key;
        words >> key;
        if (key == "kernel") words >> kernel;
        if (key == "options") options = line;
        if (key == "arg") {
            CapturedArg arg;
            words >> arg.index >> arg.kind >> arg.bytes >> arg.file;
            args.push_back(arg);
        }
    }
    EXPECT_EQ(kernel, "render_pass");
    EXPECT_NE(options.find(kKernelLanguageOptions), std::string::npos) << options;
    EXPECT_NE(options.find("-DORB_FILM_CHANNELS_BUILT="), std::string::npos) << options;  // never all 32 bits
    EXPECT_GT(std::filesystem::file_size(dir.path() / "program.bin"), 0u);

    // One line per argument, in the kernel's order: the film channels, then
    // each scene table, then the parameters, then the active pixels.
    const int film_args = film::kChannelCount;
    ASSERT_EQ(args.size(), static_cast<std::size_t>(PassArg::count) + 1);
    ASSERT_EQ(args.size(), film_args + kSceneTableCount + 2);
    for (std::size_t i = 0; i < args.size(); ++i) {
        EXPECT_EQ(args[i].index, static_cast<int>(i));
        EXPECT_EQ(args[i].kind, i < static_cast<std::size_t>(film_args) ? "film"
                                : i + 2 == args.size()                   ? "value"
                                                                         : "buffer");
        EXPECT_EQ(std::filesystem::file_size(dir.path() / args[i].file), args[i].bytes) << args[i].file;
    }

    // The film arguments: the film after the first pass, and after the second.
    for (int c = 0; c < film_args; ++c) {
        const auto channel = static_cast<film::Channel>(c);
        const std::string name = film::info(channel).name;
        EXPECT_EQ(read_bytes(dir.path() / args[c].file), bytes_of(before, channel)) << name << " before";
        EXPECT_EQ(read_bytes(dir.path() / ("arg" + std::to_string(c) + ".after.bin")),
                  bytes_of(after, channel))
            << name << " after";
    }
    EXPECT_NE(bytes_of(before, film::Channel::radiance), bytes_of(after, film::Channel::radiance))
        << "the pass added light";

    // The parameters: the second pass's.
    const std::vector<char> params_bytes = read_bytes(dir.path() / args.back().file);
    device::RenderPassParams params{};
    ASSERT_EQ(params_bytes.size(), sizeof params);
    std::memcpy(&params, params_bytes.data(), sizeof params);
    EXPECT_EQ(params.pass.sample_count, 2);
    EXPECT_EQ(params.pass.first_sample_lo, 1u);
    EXPECT_EQ(params.pass.write_centre_ray, 0);
    EXPECT_EQ(params.settings.width, 24);
    EXPECT_EQ(params.settings.seed_lo, 11u);
}

// `skip` lets that many candidate passes go by; with more skipped than
// there are passes, nothing is written.
TEST(PassCapture, SkipsTheCandidatesItIsToldTo)
{
    Scene scene;
    scene.camera.position = {0.0, 1.0, 4.0};
    scene.camera.target = {0.0, 1.0, 0.0};
    add_sphere(scene, {0.0, 0.0, 0.0}, 50.0, add_material(scene, MaterialType::Diffuse, {0.7, 0.7, 0.7}));
    add_sphere(scene, {0.0, 4.0, 0.0}, 0.8, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {8, 8, 8}));
    RenderConfig config = small_config(16, 8, 3);

    const CaptureDir third;
    const auto capture = std::make_shared<PassCapture>(third.path().string(), 1);
    config.development.pass_observer = capture;
    test::render(scene, config, {1, 2, 3, 4});
    ASSERT_TRUE(capture->taken());
    std::ifstream launch(third.path() / "launch.txt");
    std::string line, params_file;
    while (std::getline(launch, line))
        if (line.rfind("arg ", 0) == 0 && line.find(" value ") != std::string::npos)
            params_file = line.substr(line.rfind(' ') + 1);
    ASSERT_FALSE(params_file.empty());
    const std::vector<char> bytes = read_bytes(third.path() / params_file);
    device::RenderPassParams params{};
    ASSERT_EQ(bytes.size(), sizeof params);
    std::memcpy(&params, bytes.data(), sizeof params);
    EXPECT_EQ(params.pass.sample_count, 3);  // passes of 1 (centre rays), 2 (skipped), 3
    EXPECT_EQ(params.pass.first_sample_lo, 3u);

    const CaptureDir none;
    const auto late = std::make_shared<PassCapture>(none.path().string(), 5);
    config.development.pass_observer = late;
    test::render(scene, config, {1, 2, 3, 4});
    EXPECT_FALSE(late->taken());
    EXPECT_FALSE(std::filesystem::exists(none.path()));
}
