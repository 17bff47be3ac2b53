// The BVH changes how spheres are found, never what is found: the same seed
// renders the same image with the tree and with every ray testing every
// sphere, on scenes with spheres in the tree, huge spheres outside it, every
// material and many lights.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <limits>
#include <map>
#include <future>
#include <random>
#include <sstream>

#include "render_test_support.h"
#include "scene_layout.h"

using namespace orb;
using namespace orb::render;
using namespace orb::render::test;

namespace {

// A floor of radius 1e4 (kept outside the tree), a cloud of small spheres of
// every material, and a dozen small lights among them, seen from above.
Scene cloud_scene(int spheres, std::uint32_t seed) {
    Scene scene;
    scene.camera.position = {0.0, 6.0, 14.0};
    scene.camera.target = {0.0, 1.0, 0.0};
    scene.camera.up = {0.0, 1.0, 0.0};
    scene.camera.vfov_deg = 40.0;
    const auto white = add_material(scene, MaterialType::Diffuse, {0.7, 0.7, 0.7});
    const auto red = add_material(scene, MaterialType::Diffuse, {0.8, 0.2, 0.2});
    const auto mirror = add_material(scene, MaterialType::Mirror, {0.9, 0.9, 0.9});
    const auto glass = add_material(scene, MaterialType::Dielectric, {1.0, 1.0, 1.0}, {0, 0, 0}, 1.5);
    const auto lamp = add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {6.0, 5.5, 5.0});
    add_sphere(scene, {0.0, -1e4, 0.0}, 1e4, white);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> x(-5.0, 5.0), y(0.2, 4.0), r(0.1, 0.45);
    const std::uint32_t kinds[] = {white, red, mirror, glass};
    for (int i = 0; i < spheres; ++i)
        add_sphere(scene, {x(rng), y(rng), x(rng)}, r(rng), i % 25 == 0 ? lamp : kinds[i % 4]);
    return scene;
}

// A channel's sums or centre-ray values, bit for bit.
template <typename Value>
void expect_identical(const std::vector<Value>& a, const std::vector<Value>& b, const char* channel) {
    ASSERT_EQ(a.size(), b.size()) << channel;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.size(); ++i) differing += a[i] != b[i];
    EXPECT_EQ(differing, 0u) << channel << ": " << differing << " of " << a.size() << " values differ";
}

// Every pass of the same seed's render, with the tree and without it, the
// kernels built with `cl_options` added (the development knob
// ORB_CL_OPTIONS; nullptr: none).
void expect_same_with_and_without_tree(const Scene& scene, const char* cl_options = nullptr)
{
    for (IntegratorMode mode : {IntegratorMode::Global, IntegratorMode::Direct}) {
        RenderConfig with = small_config(48, 36, 11, 6, mode);
        if (cl_options) with.development.cl_options = cl_options;
        RenderConfig without = with;
        without.use_bvh = false;
        // Both with render_pass: without a tree the CPU would otherwise render
        // with lanes, whose rounding differs (simd_kernel_test.cpp).
        const Film a = render_with_simd_lanes(scene, with, {4}, "0"), b = render_with_simd_lanes(scene, without, {4}, "0");
        expect_identical(a.radiance, b.radiance, "radiance");
        expect_identical(a.direct, b.direct, "direct");
        expect_identical(a.indirect, b.indirect, "indirect");
        expect_identical(a.albedo, b.albedo, "albedo");
        expect_identical(a.alpha, b.alpha, "alpha");
        expect_identical(a.depth, b.depth, "depth");
        expect_identical(a.object_id, b.object_id, "object id");  // scene indices, not table slots
    }
}

}  // namespace

TEST(BvhRender, SameImageWithAndWithoutTheTree) {
    const Scene scene = cloud_scene(300, 5);
    // The tree has nodes with empty lanes (their inverted boxes must never be
    // entered) and leaves of fewer than four spheres (padding lanes).
    const SceneLayout layout = layout_scene(scene);
    std::size_t empty_lanes = 0;
    for (const device::BvhNodeRecord& node : layout.tables.bvh_nodes)
        for (float lo_x : {node.bounds[0].x, node.bounds[0].y, node.bounds[0].z, node.bounds[0].w})
            empty_lanes += lo_x == std::numeric_limits<float>::max();
    EXPECT_GT(empty_lanes, 0u);
    std::size_t padding_lanes = 0;
    for (const device::SpherePacket& packet : layout.tables.packets)
        for (float r2 : {packet.radius2.x, packet.radius2.y, packet.radius2.z, packet.radius2.w}) padding_lanes += r2 < 0.0f;
    EXPECT_GT(padding_lanes, 0u);
    expect_same_with_and_without_tree(scene);
}

// A node whose children are all leaves names their packets as one run
// (BvhNodeRecord::leaf_run), which the CPU variant tests without the boxes:
// the run is exactly the children's packets, consecutive; any other node
// has none.
TEST(BvhRender, LeafRunsNameExactlyTheLeavesOfAllLeafNodes) {
    const SceneLayout layout = layout_scene(cloud_scene(2000, 3));
    std::size_t runs = 0, others = 0;
    for (const device::BvhNodeRecord& node : layout.tables.bvh_nodes) {
        // Empty lanes hold child -1, which reads as packet 0: count the
        // node's real children from its boxes (an empty lane's box is inverted).
        std::vector<int> real_leaves;
        bool only_leaves = true;
        int real = 0;
        const int child_of[4] = {node.child.x, node.child.y, node.child.z, node.child.w};
        const float lo_x[4] = {node.bounds[0].x, node.bounds[0].y, node.bounds[0].z, node.bounds[0].w};
        const float hi_x[4] = {node.bounds[3].x, node.bounds[3].y, node.bounds[3].z, node.bounds[3].w};
        for (int k = 0; k < 4; ++k) {
            if (lo_x[k] > hi_x[k]) continue;  // an empty lane
            ++real;
            if (child_of[k] < 0) real_leaves.push_back(-1 - child_of[k]);
            else only_leaves = false;
        }
        if (only_leaves && real > 0) {
            ++runs;
            ASSERT_EQ(node.leaf_run.y, real);
            for (int k = 0; k < real; ++k) EXPECT_EQ(real_leaves[k], node.leaf_run.x + k);
        } else {
            ++others;
            EXPECT_EQ(node.leaf_run.x, -1);
        }
    }
    EXPECT_GT(runs, 0u);
    EXPECT_GT(others, 0u);
}

// GPUs build the kernels with one-sphere-at-a-time intersection
// (ORB_SCALAR_TRAVERSAL, ORB_DRAW_ALL_NUMBERS); its traversal must find the same spheres too. Run
// here on PoCL through the development knob ORB_CL_OPTIONS.
void expect_same_with_and_without_tree_in_gpu_traversal(int warp_vote) {
    const Scene scene = cloud_scene(300, 5);
    expect_same_with_and_without_tree(scene, device::kernel_feature_options(gpu_traversal(scene, warp_vote)).c_str());
}

TEST(BvhRender, SameImageWithAndWithoutTheTreeInTheGpuVariant) {
    expect_same_with_and_without_tree_in_gpu_traversal(0);
}

// NVIDIA GPUs traverse speculatively (a warp vote decides when lanes test
// leaves: warp_vote.cl). ORB_WARP_VOTE=2 runs the same control flow here,
// every lane speculating as far as it can.
TEST(BvhRender, SameImageWithAndWithoutTheTreeInSpeculativeTraversal) {
    expect_same_with_and_without_tree_in_gpu_traversal(2);
}

// What the kernels print while rendering `scene` with the kernel features
// of `features` that differ from the defaults added to their build options
// (the development knob ORB_CL_OPTIONS).
std::string kernel_output(const Scene& scene, const device::KernelFeatures& features)
{
    testing::internal::CaptureStdout();
    try {
        render_with_cl_options(scene, small_config(48, 36, 11, 6), {4},
                               device::kernel_feature_options(features).c_str());
    } catch (...) {
        testing::internal::GetCapturedStdout();
        throw;
    }
    std::fflush(stdout);
    return testing::internal::GetCapturedStdout();
}

// The features `base` with the traversal's bounds checks on, and the
// checked stack limited to `stack_limit` (0: the traversal's own).
device::KernelFeatures checked(device::KernelFeatures base, int stack_limit = 0)
{
    base.bvh_check = true;
    base.bvh_check_stack = stack_limit;
    return base;
}

// With the traversal's bounds checks on (ORB_BVH_CHECK), no node, packet
// or stack index leaves its table, in the CPU variant and in the GPU variant
// reading the scene from __global memory as GPUs do for large scenes, and in
// the speculative traversal. With
// the checked stack limit lowered to 2, the checks do report.
TEST(BvhRender, TraversalIndicesStayInBoundsInBothVariants) {
    const Scene scene = cloud_scene(300, 5);
    device::KernelFeatures gpu_global = gpu_traversal(scene);
    gpu_global.scene_space = "__global";
    device::KernelFeatures voting = device::KernelFeatures{};
    voting.warp_vote = 2;
    EXPECT_EQ(kernel_output(scene, checked({})), "");
    EXPECT_EQ(kernel_output(scene, checked(gpu_global)), "");
    EXPECT_EQ(kernel_output(scene, checked(gpu_traversal(scene, 2))), "");
    EXPECT_NE(kernel_output(scene, checked({}, 2)).find("orb BVH check: stack top"), std::string::npos);
    EXPECT_NE(kernel_output(scene, checked(voting, 2)).find("orb BVH check: stack top"), std::string::npos);
}

// The development counters (-DORB_BVH_COUNT=1, scripts/bvh-visits.sh)
// print one line per ray that enters the tree, closest hits and shadow rays,
// each with a visit count between one (the root) and every node and leaf
// of the tree; in both variants and in the speculative traversal.
TEST(BvhRender, VisitCountersReportEveryTracedRay) {
    const Scene scene = cloud_scene(300, 5);
    const SceneLayout layout = layout_scene(scene);
    std::size_t leaves = 0;
    for (const device::BvhNodeRecord& node : layout.tables.bvh_nodes)
        for (int child : {node.child.x, node.child.y, node.child.z, node.child.w}) leaves += child < 0;
    const long most = static_cast<long>(layout.tables.bvh_nodes.size() + leaves);
    for (device::KernelFeatures features : {device::KernelFeatures{}, gpu_traversal(scene), gpu_traversal(scene, 2)}) {
        features.bvh_count = true;
        const std::string options = device::kernel_feature_options(features);
        std::istringstream lines(kernel_output(scene, features));
        std::map<std::string, long> rays;
        std::string line;
        while (std::getline(lines, line)) {
            char kind[16] = {};
            long visits = 0;
            ASSERT_EQ(std::sscanf(line.c_str(), "orb BVH visits: %15s %ld", kind, &visits), 2) << options << ": " << line;
            EXPECT_GE(visits, 1) << line;
            EXPECT_LE(visits, most) << line;
            ++rays[kind];
        }
        EXPECT_EQ(rays.size(), 2u) << options;
        // Every camera ray starts a traversal (48x36 pixels at 4 spp).
        EXPECT_GE(rays["closest"], 48 * 36 * 4) << options;
        EXPECT_GT(rays["shadow"], 0) << options;
    }
}

TEST(BvhRender, TheIdPassNamesSceneSpheresInBvhOrder) {
    const Scene scene = cloud_scene(200, 9);
    const Film film = test::render(scene, small_config(64, 48), {1});
    std::size_t inside_cloud = 0;
    for (float id : film.object_id) {
        ASSERT_GE(id, -1.0f);
        ASSERT_LT(id, static_cast<float>(scene.spheres.size()));
        inside_cloud += id >= 1.0f;
    }
    EXPECT_GT(inside_cloud, film.object_id.size() / 20);  // the cloud is in view
}

// Frames: Renderer::set_scene refits the last frame's tree to spheres that
// moved a little, and that tree finds the same spheres as a new build, so
// the frame's image is the one a new renderer makes. Spheres thrown
// elsewhere make the refitted tree too costly, and it is built anew.
TEST(BvhRender, AFrameWithARefittedTreeIsTheImageOfANewBuild) {
    Scene scene = cloud_scene(300, 5);
    const RenderConfig config = small_config(48, 36, 11, 6);
    Renderer animated(scene, config);
    EXPECT_FALSE(animated.last_tree_refitted());
    std::mt19937 rng(6);
    std::normal_distribution<double> step(0.0, 0.02);
    for (std::size_t i = 1; i < scene.spheres.size(); ++i)  // the floor (sphere 0) stays
        for (double& c : scene.spheres[i].center) c += step(rng);
    animated.set_scene(scene);
    EXPECT_TRUE(animated.last_tree_refitted());
    animated.render_pass(4);
    const Film refitted = animated.read_film();
    const Film rebuilt = test::render(scene, config, {4});
    expect_identical(refitted.radiance, rebuilt.radiance, "radiance");
    expect_identical(refitted.indirect, rebuilt.indirect, "indirect");
    expect_identical(refitted.depth, rebuilt.depth, "depth");
    expect_identical(refitted.object_id, rebuilt.object_id, "object id");

    std::uniform_real_distribution<double> anywhere(-5.0, 5.0);
    for (std::size_t i = 1; i < scene.spheres.size(); ++i) scene.spheres[i].center = {anywhere(rng), 2.0, anywhere(rng)};
    animated.set_scene(scene);
    EXPECT_FALSE(animated.last_tree_refitted());
}

// The next frame's scene laid out (its tree refitted) on another thread
// while this frame renders, then uploaded: the frames are the images of
// scenes set the plain way, and the tree reported is the one in use.
TEST(BvhRender, AFramePreparedWhileTheLastRendersIsTheSameImage) {
    Scene first = cloud_scene(300, 5);
    const RenderConfig config = small_config(48, 36, 11, 6);
    Scene second = first;
    std::mt19937 rng(8);
    std::normal_distribution<double> step(0.0, 0.02);
    for (std::size_t i = 1; i < second.spheres.size(); ++i)
        for (double& c : second.spheres[i].center) c += step(rng);

    Renderer plain(first, config);
    plain.render_pass(3);
    plain.set_scene(second);
    plain.render_pass(3);
    const Film expected = plain.read_film();

    Renderer ahead(first, config);
    const Renderer::TreeReport first_tree = ahead.tree_report();
    std::future<PreparedScene> next = std::async(std::launch::async, [&] { return ahead.prepare_scene(second); });
    ahead.render_pass(3);  // the first frame renders while the second is laid out
    EXPECT_EQ(ahead.tree_report().nodes, first_tree.nodes);  // still the first frame's tree
    ahead.set_scene(next.get());
    EXPECT_TRUE(ahead.last_tree_refitted());
    ahead.render_pass(3);
    const Film film = ahead.read_film();
    expect_identical(film.radiance, expected.radiance, "radiance");
    expect_identical(film.depth, expected.depth, "depth");
    expect_identical(film.object_id, expected.object_id, "object id");
}
