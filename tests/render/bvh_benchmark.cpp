// Not a test: times the host BVH build (docs/performance.md).
//   build/bin/orb-bvh-benchmark [spheres=1000000] [threads=0 (all)]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <utility>
#include <vector>

#include "sphere_bvh.h"

namespace {

// The longest root-to-leaf path and the mean leaf depth: the device's
// traversal stack holds at most one entry per level (kBvhMaxDepth).
std::pair<int, double> leaf_depths(const orb::render::SphereBvh& bvh)
{
    if (bvh.nodes.empty()) return {0, 0.0};
    int deepest = 0;
    double depth_sum = 0;
    std::size_t leaves = 0;
    std::vector<std::pair<std::uint32_t, int>> pending{{0u, 1}};
    while (!pending.empty()) {
        const auto [index, depth] = pending.back();
        pending.pop_back();
        const orb::render::BvhNode& node = bvh.nodes[index];
        if (node.count > 0) {
            deepest = std::max(deepest, depth);
            depth_sum += depth;
            ++leaves;
        } else {
            pending.push_back({node.first, depth + 1});
            pending.push_back({node.first + 1, depth + 1});
        }
    }
    return {deepest, depth_sum / static_cast<double>(leaves)};
}

}  // namespace

int main(int argc, char** argv) {
    const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
    orb::render::BvhSettings settings;
    settings.threads = argc > 2 ? static_cast<unsigned>(std::atoi(argv[2])) : 0;
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> pos(-100.0, 100.0), rad(0.05, 0.5);
    std::vector<orb::Sphere> spheres(n);
    for (auto& s : spheres) {
        s.center = {pos(rng), pos(rng), pos(rng)};
        s.radius = rad(rng);
    }
    for (int run = 0; run < 3; ++run) {
        const auto start = std::chrono::steady_clock::now();
        const orb::render::SphereBvh bvh = orb::render::build_sphere_bvh(spheres, settings);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const auto [deepest, mean_depth] = leaf_depths(bvh);
        std::printf("spheres=%zu threads=%u nodes=%zu max_depth=%d mean_leaf_depth=%.1f build_seconds=%.3f\n", n,
                    settings.threads, bvh.nodes.size(), deepest, mean_depth, seconds);
    }
}
