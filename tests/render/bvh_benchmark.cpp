// Not a test: times the host BVH build (docs/design/bvh-layout.md).
//   build/bin/orb-bvh-benchmark [spheres=1000000] [threads=0 (all)]
//   build/bin/orb-bvh-benchmark --scene FILE [threads=0 (all)]
// The first form builds over uniformly random spheres; the second over a
// scene's spheres (any format orb-render reads), as orb-render does. Each
// run prints the binary SAH build's and the 4-wide collapse's seconds.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

#include "benchmark_support.h"
#include "sphere_bvh.h"

namespace {

using orb::bench::seconds_since;

std::vector<orb::Sphere> random_spheres(std::size_t n)
{
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> pos(-100.0, 100.0), rad(0.05, 0.5);
    std::vector<orb::Sphere> spheres(n);
    for (auto& s : spheres) {
        s.center = {pos(rng), pos(rng), pos(rng)};
        s.radius = rad(rng);
    }
    return spheres;
}

std::vector<orb::Sphere> scene_spheres(const char* path) { return orb::bench::import_scene_file(path).spheres; }

}  // namespace

int main(int argc, char** argv) {
    try {
        const bool from_scene = argc > 2 && std::string(argv[1]) == "--scene";
        const std::vector<orb::Sphere> spheres =
            from_scene ? scene_spheres(argv[2]) : random_spheres(argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000);
        const int threads_arg = from_scene ? 3 : 2;
        orb::render::BvhSettings settings;
        settings.threads = argc > threads_arg ? static_cast<unsigned>(std::atoi(argv[threads_arg])) : 0;
        for (int run = 0; run < 3; ++run) {
            const auto start = std::chrono::steady_clock::now();
            const orb::render::BinaryBvh binary = orb::render::build_binary_bvh(spheres, settings);
            const double binary_seconds = seconds_since(start);
            const orb::render::SphereBvh bvh = orb::render::collapse_to_4_wide(binary);
            const double seconds = seconds_since(start);
            std::printf("spheres=%zu threads=%u nodes=%zu max_depth=%d stack_bound=%d build_seconds=%.3f "
                        "binary_seconds=%.3f collapse_seconds=%.3f\n",
                        spheres.size(), settings.threads, bvh.nodes.size(), orb::render::bvh_depth(bvh),
                        orb::render::bvh_stack_bound(bvh), seconds, binary_seconds, seconds - binary_seconds);
        }
    } catch (const std::exception& error) {
        std::cerr << "orb-bvh-benchmark: error: " << error.what() << "\n";
        return 1;
    }
}
