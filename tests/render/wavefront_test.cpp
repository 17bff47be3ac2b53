// The wavefront prototype (kernels/wavefront.cl, WavefrontRenderer) against
// render_pass: it runs render_pass's own shading cut at the ray casts and
// draws the same numbers for each pixel, sample and vertex, so the two
// render the same paths (up to float rounding, as render_pass_simd:
// expect_mostly_same_paths). Its waves of several paths per pixel render
// the same samples as single waves.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <vector>

#include "orb/render/device.h"
#include "render_test_support.h"
#include "scene_layout.h"
#include "wavefront_renderer.h"

using namespace orb;
using namespace orb::render;
using namespace orb::render::test;

namespace {

// every_branch_scene() with `cloud` small diffuse and glass spheres among
// its balls, enough for a tree.
Scene scene_with(int cloud)
{
    Scene scene = every_branch_scene();
    const auto red = add_material(scene, MaterialType::Diffuse, {0.8, 0.2, 0.2});
    const auto glass = add_material(scene, MaterialType::Dielectric, {1.0, 0.95, 0.9}, {0, 0, 0}, 1.5);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> xz(-3.0, 3.0), y(1.6, 3.0), r(0.02, 0.12);
    for (int i = 0; i < cloud; ++i) add_sphere(scene, {xz(rng), y(rng), xz(rng) - 1.0}, r(rng), i % 7 == 0 ? glass : red);
    return scene;
}

// The radiance sums of `waves` waves of `paths_per_pixel` samples per pixel, from sample 0.
std::vector<float> render_waves(const Scene& scene, const RenderConfig& config, int paths_per_pixel, int waves)
{
    const SceneLayout layout = layout_scene(scene);
    WavefrontRenderer renderer(DeviceSession::open(choose_device(""), {}), layout,
                               layout_camera(scene.camera, config.width, config.height), config, paths_per_pixel);
    renderer.enqueue(0, waves);
    return renderer.radiance_sums();
}

void expect_same_paths_as_render_pass(const Scene& scene, const RenderConfig& config, int spp, const char* what)
{
    const Film film = render_with_simd_lanes(scene, config, {spp}, "0");
    const std::vector<float> waves = render_waves(scene, config, 1, spp);
    double total = 0;
    for (float v : waves) total += v;
    EXPECT_GT(total, 0.0) << what;
    expect_mostly_same_paths(waves, film.radiance, what);
}

TEST(Wavefront, SamePathsAsRenderPassWithGlassMirrorsAndALens)
{
    const Scene scene = scene_with(0);
    expect_same_paths_as_render_pass(scene, small_config(40, 30, 3), 8, "Sobol");
    RenderConfig independent = small_config(40, 30, 4);
    independent.sampler = SamplerKind::Independent;
    expect_same_paths_as_render_pass(scene, independent, 8, "independent");
}

// wavefront_begin starts its paths with render_pass's camera_ray, orthographic too.
TEST(Wavefront, SamePathsAsRenderPassWithAnOrthographicThinLens)
{
    Scene scene = scene_with(0);
    scene.camera.orthographic_height = 6.0;
    expect_same_paths_as_render_pass(scene, small_config(40, 30, 3), 8, "orthographic");
}

TEST(Wavefront, SamePathsAsRenderPassThroughATree)
{
    const Scene scene = scene_with(600);
    ASSERT_GT(layout_scene(scene).counts.bvh_node_count, 0);
    expect_same_paths_as_render_pass(scene, small_config(40, 30, 5), 8, "tree");
}

TEST(Wavefront, WavesOfSeveralPathsPerPixelRenderTheSameSamples)
{
    const Scene scene = scene_with(0);
    const RenderConfig config = small_config(24, 18, 6);
    const std::vector<float> one = render_waves(scene, config, 1, 4);
    expect_same_up_to_rounding(one, render_waves(scene, config, 2, 2), 4, "two paths per pixel");
    expect_same_up_to_rounding(one, render_waves(scene, config, 4, 1), 4, "four paths per pixel");
}

TEST(Wavefront, RefusesDirectMode)
{
    const Scene scene = scene_with(0);
    const SceneLayout layout = layout_scene(scene);
    EXPECT_THROW(WavefrontRenderer(DeviceSession::open(choose_device(""), {}), layout,
                                   layout_camera(scene.camera, 8, 8), small_config(8, 8, 1, 6, IntegratorMode::Direct)),
                 std::invalid_argument);
}

}  // namespace
