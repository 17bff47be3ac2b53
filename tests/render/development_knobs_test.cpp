// The development knobs reach the renderer through RenderConfig::development
// alone (the library reads no environment for them): the kernel and its
// lanes, the work-group shape and the build options of the passes that
// actually run, seen through the pass observer seam, and the refit limit of
// an animation's tree.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "pass_observer.h"
#include "render_test_support.h"

using namespace orb;
using namespace orb::render;
using namespace orb::render::test;

namespace {

// What one observed pass was: the kernel, its program's build options, the
// work sizes and the samples it added.
struct SeenPass {
    std::string kernel;
    std::string options;
    std::size_t global_x = 0, global_y = 0, local_x = 0, local_y = 0;
    int samples = 0;
    bool finished = false;
};

class RecordingObserver final : public PassObserver {
public:
    explicit RecordingObserver(bool wants_finish) : wants_finish_(wants_finish) {}

    bool pass_launching(cl::CommandQueue& queue, const PassLaunch& launch) override
    {
        SeenPass pass;
        pass.kernel = launch.kernel.getInfo<CL_KERNEL_FUNCTION_NAME>();
        // Some drivers count the terminating NUL in the name's length.
        pass.kernel.erase(pass.kernel.find_last_not_of('\0') + 1);
        pass.options = launch.program.getBuildInfo<CL_PROGRAM_BUILD_OPTIONS>(queue.getInfo<CL_QUEUE_DEVICE>());
        pass.global_x = launch.global[0], pass.global_y = launch.global[1];
        pass.local_x = launch.local[0], pass.local_y = launch.local[1];
        pass.samples = launch.params.pass.sample_count;
        passes.push_back(pass);
        return wants_finish_;
    }
    void pass_finished(cl::CommandQueue&, const PassLaunch& launch) override
    {
        ASSERT_FALSE(passes.empty());
        EXPECT_EQ(launch.params.pass.sample_count, passes.back().samples);
        passes.back().finished = true;
    }

    std::vector<SeenPass> passes;

private:
    bool wants_finish_;
};

Scene small_scene()
{
    Scene scene;
    scene.camera.position = {0.0, 1.0, 4.0};
    scene.camera.target = {0.0, 1.0, 0.0};
    add_sphere(scene, {0.0, -1e4, 0.0}, 1e4, add_material(scene, MaterialType::Diffuse, {0.7, 0.7, 0.7}));
    add_sphere(scene, {0.0, 4.0, 0.0}, 0.8, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {8, 8, 8}));
    add_sphere(scene, {0.5, 0.6, 0.0}, 0.5, add_material(scene, MaterialType::Diffuse, {0.8, 0.2, 0.2}));
    return scene;
}

// The passes `config` renders (two, of 1 and 2 samples), as observed.
std::vector<SeenPass> observed_passes(RenderConfig config, bool wants_finish = false)
{
    auto observer = std::make_shared<RecordingObserver>(wants_finish);
    config.development.pass_observer = observer;
    Renderer renderer(small_scene(), config);
    renderer.render_pass(1);
    renderer.render_pass(2);
    renderer.read_film();
    return observer->passes;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Whether `option` is one of the whitespace-separated words of `options`.
bool has_option(const std::string& options, const std::string& option)
{
    std::istringstream words(options);
    std::string word;
    while (words >> word)
        if (word == option) return true;
    return false;
}

// Whether the tests' device is a GPU (there every width is render_pass).
bool device_is_gpu() { return Renderer(small_scene(), small_config(4, 4)).device().is_gpu; }

}  // namespace

TEST(DevelopmentKnobs, TheObserverSeesEveryPassAndItsEndWhenAsked)
{
    const std::vector<SeenPass> unfinished = observed_passes(small_config(20, 12));
    ASSERT_EQ(unfinished.size(), 2u);
    EXPECT_EQ(unfinished[0].samples, 1);
    EXPECT_EQ(unfinished[1].samples, 2);
    EXPECT_FALSE(unfinished[0].finished || unfinished[1].finished);

    const std::vector<SeenPass> finished = observed_passes(small_config(20, 12), true);
    ASSERT_EQ(finished.size(), 2u);
    EXPECT_TRUE(finished[0].finished && finished[1].finished);
}

// ORB_SIMD_LANES: 4 and 8 build render_pass with that many lanes (one
// work-item per that many pixels of a row), 0 with one.
TEST(DevelopmentKnobs, SimdLanesPickTheKernelAndItsWidth)
{
    if (device_is_gpu()) GTEST_FAIL() << "these tests expect PoCL's CPU device";
    RenderConfig config = small_config(40, 12);
    for (int lanes : {4, 8}) {
        config.development.simd_lanes = lanes;
        const std::vector<SeenPass> passes = observed_passes(config);
        ASSERT_FALSE(passes.empty());
        EXPECT_EQ(passes[0].kernel, "render_pass") << lanes;
        EXPECT_TRUE(has_option(passes[0].options, "-DORB_LANES=" + std::to_string(lanes)))
            << passes[0].options;
        EXPECT_EQ(passes[0].global_x, static_cast<std::size_t>(40 / lanes)) << lanes;  // local size 1x1
    }
    config.development.simd_lanes = 0;
    const std::vector<SeenPass> scalar = observed_passes(config);
    ASSERT_FALSE(scalar.empty());
    EXPECT_EQ(scalar[0].kernel, "render_pass");
    EXPECT_FALSE(contains(scalar[0].options, "ORB_LANES")) << scalar[0].options;
    EXPECT_EQ(scalar[0].global_x, 40u);
}

// ORB_LOCAL_SIZE: the work-group shape of render_pass, the global size
// rounded up to whole groups.
TEST(DevelopmentKnobs, LocalSizeShapesTheWorkGroups)
{
    RenderConfig config = small_config(20, 12);
    config.development.simd_lanes = 0;
    config.development.local_size = LocalSize{4, 8};
    const std::vector<SeenPass> passes = observed_passes(config);
    ASSERT_FALSE(passes.empty());
    EXPECT_EQ(passes[0].local_x, 4u);
    EXPECT_EQ(passes[0].local_y, 8u);
    EXPECT_EQ(passes[0].global_x, 20u);
    EXPECT_EQ(passes[0].global_y, 16u);
}

// ORB_CL_OPTIONS: appended last to the program's build options.
TEST(DevelopmentKnobs, ClOptionsEndTheBuildOptions)
{
    RenderConfig config = small_config(20, 12);
    config.development.cl_options = "-DORB_KNOB_TEST_MARK=3";
    const std::vector<SeenPass> passes = observed_passes(config);
    ASSERT_FALSE(passes.empty());
    const std::string& options = passes[0].options;
    const std::string mark = " -DORB_KNOB_TEST_MARK=3";
    ASSERT_GE(options.size(), mark.size()) << options;
    EXPECT_EQ(options.substr(options.size() - mark.size()), mark) << options;
    EXPECT_FALSE(contains(observed_passes(small_config(20, 12))[0].options, "ORB_KNOB_TEST_MARK"));
}

// ORB_REFIT_COST_LIMIT: 0 never refits a tree the default rule would keep;
// a large limit refits one the default rule would build anew.
TEST(DevelopmentKnobs, RefitCostLimitReplacesTheRefitRule)
{
    Scene scene;
    scene.camera.position = {0.0, 6.0, 14.0};
    scene.camera.target = {0.0, 1.0, 0.0};
    add_sphere(scene, {0.0, -1e4, 0.0}, 1e4, add_material(scene, MaterialType::Diffuse, {0.7, 0.7, 0.7}));
    const auto lamp = add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {6, 6, 6});
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> x(-5.0, 5.0), y(0.2, 4.0);
    for (int i = 0; i < 300; ++i) add_sphere(scene, {x(rng), y(rng), x(rng)}, 0.2, lamp);
    Scene nudged = scene, scattered = scene;
    std::normal_distribution<double> step(0.0, 0.02);
    for (std::size_t i = 1; i < scene.spheres.size(); ++i) {
        for (double& c : nudged.spheres[i].center) c += step(rng);
        scattered.spheres[i].center = {x(rng), 2.0, x(rng)};
    }
    const auto refits = [&](std::optional<double> limit, const Scene& next) {
        RenderConfig config = small_config(16, 12);
        config.development.refit_cost_limit = limit;
        Renderer renderer(scene, config);
        renderer.set_scene(next);
        return renderer.last_tree_refitted();
    };
    EXPECT_TRUE(refits(std::nullopt, nudged));
    EXPECT_FALSE(refits(0.0, nudged));
    EXPECT_FALSE(refits(std::nullopt, scattered));
    EXPECT_TRUE(refits(1e6, scattered));
}

// No knob comes from the environment inside the library: a variable a
// script sets does nothing unless a tool reads it into the config.
TEST(DevelopmentKnobs, TheLibraryIgnoresTheEnvironment)
{
    ::setenv("ORB_CL_OPTIONS", "-DORB_KNOB_TEST_MARK=4", 1);
    ::setenv("ORB_LOCAL_SIZE", "2x2", 1);
    RenderConfig config = small_config(20, 12);
    config.development.simd_lanes = 0;
    const std::vector<SeenPass> passes = observed_passes(config);
    ::unsetenv("ORB_CL_OPTIONS");
    ::unsetenv("ORB_LOCAL_SIZE");
    ASSERT_FALSE(passes.empty());
    EXPECT_FALSE(contains(passes[0].options, "ORB_KNOB_TEST_MARK")) << passes[0].options;
    EXPECT_FALSE(passes[0].local_x == 2 && passes[0].local_y == 2);
}
