// render_pass built with camera paths in SIMD lanes (ORB_LANES 4, 8 or 16,
// kernels/lanes.cl: PoCL's default) against the same text built for one
// path per work-item (ORB_LANES=1, what GPUs run): each lane draws the same
// numbers for each pixel, sample and vertex and follows the same estimator,
// so the two render the same paths. Only where float rounding differs (fused multiply-adds, a
// reciprocal square root for a normalize) can a path take another branch
// near an edge or a roulette threshold. The checks: most values agree up to
// rounding, the centre-ray channels exactly, and the two images agree in
// the mean within the standard error of their paired differences (no bias
// between the kernels). The closed forms of analytic_test.cpp run with each
// lane width as well (PlaneUnderSphereLight), and furnace_test.cpp's
// environment furnaces run with the device's lanes on PoCL.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "render_test_support.h"

using namespace orb;
using namespace orb::render;
using namespace orb::render::test;

namespace {

// Every channel of the two films: the Sum channels by expect_mostly_same_paths, the centre-ray
// channels (the same scalar code in both kernels) exactly.
void expect_same_paths(const Film& simd, const Film& scalar, const std::string& what)
{
    ASSERT_EQ(simd.samples_per_pixel, scalar.samples_per_pixel);
#define ORB_TEST_COMPARE_Sum(name) \
    expect_mostly_same_paths(sum_values(simd, film::Channel::name), sum_values(scalar, film::Channel::name), what + ", " #name);
#define ORB_TEST_COMPARE_CentreRay(name)                                                     \
    {                                                                                        \
        ASSERT_EQ(simd.name.size(), scalar.name.size());                                     \
        std::size_t differing = 0;                                                           \
        for (std::size_t i = 0; i < simd.name.size(); ++i)                                   \
            differing += simd.name[i] != scalar.name[i] && !(std::isinf(simd.name[i]) && simd.name[i] == scalar.name[i]); \
        EXPECT_EQ(differing, 0u) << what << ", " #name;                                      \
    }
#define ORB_TEST_COMPARE(name, components, clear, accumulate, ...) ORB_TEST_COMPARE_##accumulate(name)
    ORB_FILM_CHANNELS(ORB_TEST_COMPARE)
#undef ORB_TEST_COMPARE
#undef ORB_TEST_COMPARE_Sum
#undef ORB_TEST_COMPARE_CentreRay
}

// Sum of the radiance channel, to tell a render from an empty film.
double total_radiance(const Film& film)
{
    double total = 0;
    for (double v : sum_values(film, film::Channel::radiance)) total += v;
    return total;
}

// Renders `scene` with `lanes` lanes (nullptr: the device's default) and
// with one, requires a lit image and the same paths, and gives back the
// film of the lanes.
Film render_both_expecting_same_paths(const Scene& scene, const RenderConfig& config, const std::vector<int>& passes,
                                      const char* lanes, const std::string& what)
{
    Film simd = render_with_simd_lanes(scene, config, passes, lanes);
    const Film scalar = render_with_simd_lanes(scene, config, passes, "0");
    EXPECT_GT(total_radiance(simd), 0.0) << what;
    expect_same_paths(simd, scalar, what);
    return simd;
}


// Every branch of the path tracer; 37 pixels per row leave the last
// work-item's lanes partly outside the image.
TEST(SimdKernel, SamePathsAsRenderPassOnEveryBranch)
{
    const Scene scene = every_branch_scene();
    const RenderConfig config = small_config(37, 23, 5);
    render_both_expecting_same_paths(scene, config, {3, 13}, "16", "every branch");
}

// The orthographic camera, through a thin lens and as a pinhole: camera_ray's
// parallel rays over lanes.
TEST(SimdKernel, SamePathsAsRenderPassWithAnOrthographicCamera)
{
    Scene scene = every_branch_scene();
    scene.camera.orthographic_height = 6.0;
    const RenderConfig config = small_config(37, 23, 5);
    render_both_expecting_same_paths(scene, config, {2, 14}, "16", "orthographic thin lens");
    scene.camera.aperture = 0.0;
    render_both_expecting_same_paths(scene, config, {2, 14}, "16", "orthographic pinhole");
}

TEST(SimdKernel, SamePathsAsRenderPassOnSmallptGpuScenes)
{
    for (const char* name : {"cornell.scn", "caustic3.scn"}) {
        const Scene scene = load_scene_file(std::string(ORB_SCENES_DIR) + "/" + name);
        const RenderConfig config = small_config(45, 34, 3);
        render_both_expecting_same_paths(scene, config, {1, 15}, nullptr, name);
    }
}

// A cloud with a tree (each lane traverses it on its own), a floor outside
// it, and 80 lights of unequal power among 320 spheres: the lanes gather
// sphere records and alias-table slots one by one (more than 64 of each).
// The floor has radius 100, not 1e4: on a 1e4 sphere a hit point is only
// good to about 1e-3 (the float spacing there), the kernels' different
// rounding moves it by that much, and in this dense cloud of mirrors and
// glass 15% of the indirect values then part ways (with no bias: the mean
// test passed), which would hide what this test looks for.
TEST(SimdKernel, SamePathsAsRenderPassWithATreeAndManyLights)
{
    Scene scene;
    scene.camera.position = {0.0, 6.0, 14.0};
    scene.camera.target = {0.0, 1.0, 0.0};
    scene.camera.vfov_deg = 40.0;
    const std::uint32_t kinds[] = {add_material(scene, MaterialType::Diffuse, {0.7, 0.7, 0.7}),
                                   add_material(scene, MaterialType::Diffuse, {0.8, 0.2, 0.2}),
                                   add_material(scene, MaterialType::Mirror, {0.9, 0.9, 0.9}),
                                   add_material(scene, MaterialType::Dielectric, {1.0, 1.0, 1.0}, {0, 0, 0}, 1.5)};
    std::uint32_t lamps[4];
    for (int k = 0; k < 4; ++k)
        lamps[k] = add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {2.0 + 3.0 * k, 2.0 + 2.0 * k, 2.0 + k});
    add_sphere(scene, {0.0, -100.0, 0.0}, 100.0, kinds[0]);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> x(-5.0, 5.0), y(0.2, 4.0), r(0.1, 0.4);
    for (int i = 0; i < 320; ++i)
        add_sphere(scene, {x(rng), y(rng), x(rng)}, r(rng), i % 4 == 0 ? lamps[(i / 4) % 4] : kinds[i % 4]);
    const RenderConfig config = small_config(37, 23, 5);
    render_both_expecting_same_paths(scene, config, {2, 14}, "16", "tree and many lights");
}

// Under a uniform sky and no other light (the environment is the only
// light: every lane's pick is -1), and under a map of varying radiance
// beside two sphere lights (the alias table picks between them), with
// mirror and glass balls whose reflections show the sky: the escaped rays'
// MIS and the environment's next-event estimates, lane by lane.
TEST(SimdKernel, SamePathsAsRenderPassUnderAnEnvironment)
{
    Scene sky = every_branch_scene();
    sky.spheres.resize(4);  // no lamps: the floor and the three balls
    sky.environment.kind = EnvironmentKind::Color;
    sky.environment.color = {0.6, 0.7, 0.9};
    const RenderConfig config = small_config(37, 23, 5);
    render_both_expecting_same_paths(sky, config, {2, 14}, "16", "uniform sky");

    Scene mapped = every_branch_scene();
    mapped.spheres.resize(6);  // two of the three lamps
    auto image = std::make_shared<EnvironmentImage>();
    image->width = 8;
    image->height = 4;
    for (int t = 0; t < image->width * image->height; ++t)
        for (float c : {0.2f + 0.1f * static_cast<float>(t % 8), 0.5f, 0.1f + 0.3f * static_cast<float>(t / 8)})
            image->rgb.push_back(c);
    mapped.environment.kind = EnvironmentKind::Map;
    mapped.environment.map = "test.exr";
    mapped.environment.intensity = 1.5;
    mapped.environment.rotation_deg = 30.0;
    mapped.environment.image = image;
    render_both_expecting_same_paths(mapped, config, {2, 14}, "16", "map and lamps");
}

// The lane widths differ only in how pixels are grouped into work-items:
// each lane's arithmetic is the same, so 4, 8 and 16 lanes give the same
// sums up to rounding (here: exactly the same paths).
TEST(SimdKernel, EveryWidthRendersTheSamePaths)
{
    const Scene scene = every_branch_scene();
    const RenderConfig config = small_config(37, 23, 9);
    const Film sixteen = render_with_simd_lanes(scene, config, {8}, "16");
    for (const char* lanes : {"4", "8"}) {
        const Film other = render_with_simd_lanes(scene, config, {8}, lanes);
        expect_same_films_up_to_rounding(sixteen, other);
    }
}

// Passes, resumes and slices split samples the same way as at width 1:
// one pass of 16 and passes of 1, 7 and 8 hold the same samples.
TEST(SimdKernel, PassSplitsDoNotChangeTheImage)
{
    const Scene scene = every_branch_scene();
    const RenderConfig config = small_config(37, 23, 13);
    expect_same_films(render_with_simd_lanes(scene, config, {16}, "16"),
                      render_with_simd_lanes(scene, config, {1, 7, 8}, "16"));
}

// Direct mode (the paper's local illumination): every light at the first
// diffuse vertex, and the path ends after the ray that leaves it.
TEST(SimdKernel, SamePathsAsRenderPassInDirectMode)
{
    const Scene scene = every_branch_scene();
    const RenderConfig config = small_config(37, 23, 5, 6, IntegratorMode::Direct);
    const Film simd = render_both_expecting_same_paths(scene, config, {4, 12}, "16", "direct mode");
    // No path reaches a second diffuse vertex, so nothing is indirect.
    for (float v : simd.indirect) ASSERT_EQ(v, 0.0f);
}

// pbr spheres (a rough metal, a rough plastic, a smooth metal) and a rough
// glass ball beside diffuse, mirror and smooth glass: every row of the
// material table, dispatched by kind among the lanes (kernels/bsdf.cl).
TEST(SimdKernel, SamePathsAsRenderPassWithPbrAndRoughGlass)
{
    Scene scene = every_branch_scene();
    Material metal;
    metal.name = "rough metal";
    metal.type = MaterialType::Pbr;
    metal.color = {0.9, 0.7, 0.4};
    metal.roughness = 0.4;
    metal.metallic = 1.0;
    Material plastic = metal;
    plastic.name = "plastic";
    plastic.color = {0.2, 0.5, 0.8};
    plastic.metallic = 0.0;
    Material chrome = metal;
    chrome.name = "chrome";
    chrome.roughness = 0.0;
    scene.materials.push_back(metal);
    scene.materials.push_back(plastic);
    scene.materials.push_back(chrome);
    const auto first_new = static_cast<std::uint32_t>(scene.materials.size() - 3);
    scene.spheres[1].material = first_new;  // the red ball
    add_sphere(scene, {-0.6, 0.35, 1.2}, 0.35, first_new + 1);
    add_sphere(scene, {0.8, 0.3, 1.4}, 0.3, first_new + 2);
    scene.materials[scene.spheres[3].material].roughness = 0.3;  // the glass ball
    for (IntegratorMode mode : {IntegratorMode::Global, IntegratorMode::Direct}) {
        const RenderConfig config = small_config(37, 23, 5, 6, mode);
        render_both_expecting_same_paths(scene, config, {2, 14}, "16",
                                         mode == IntegratorMode::Global ? "pbr, global" : "pbr, direct");
    }
}

}  // namespace
