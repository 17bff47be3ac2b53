// Not a test: times the host BVH build (docs/performance.md).
//   build/bin/orb-bvh-benchmark [spheres=1000000] [threads=0 (all)]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "sphere_bvh.h"

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
        std::printf("spheres=%zu threads=%u nodes=%zu max_depth=%d stack_bound=%d build_seconds=%.3f\n", n,
                    settings.threads, bvh.nodes.size(), orb::render::bvh_depth(bvh), orb::render::bvh_stack_bound(bvh),
                    seconds);
    }
}
