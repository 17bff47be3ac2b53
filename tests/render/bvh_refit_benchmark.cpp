// Not a test: refit or rebuild the sphere BVH between the frames of an
// animation (docs/design/bvh-refit.md).
//   build/bin/orb-bvh-refit-benchmark [spheres=1000000] [step=0.25] [frames=8] [spp=4]
// N spheres of radius 0.2-0.5 (mean spacing about 2) in a 200-wide box on a
// floor, lit by two sphere lights, each moving `step` per frame in its own
// random direction (a particle simulation's frames). Per frame: the time to
// build a tree and to refit the previous one, their SAH costs, and the
// render time of `spp` samples per pixel at 320x240 with each tree (the
// refitted one through Renderer::set_scene, the new one in a new Renderer).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "benchmark_support.h"
#include "orb/render/renderer.h"
#include "scene_layout.h"
#include "sphere_bvh.h"

using namespace orb;
using namespace orb::render;

namespace {

using orb::bench::seconds_since;

}  // namespace

int main(int argc, char** argv)
{
    const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
    const double step = argc > 2 ? std::atof(argv[2]) : 0.25;
    const int frames = argc > 3 ? std::atoi(argv[3]) : 8;
    const int spp = argc > 4 ? std::atoi(argv[4]) : 4;

    Scene scene;
    scene.camera.position = {0.0, 180.0, 320.0};
    scene.camera.target = {0.0, 60.0, 0.0};
    scene.camera.vfov_deg = 45.0;
    Material grey;
    grey.name = "grey";
    grey.color = {0.7, 0.7, 0.7};
    Material lamp = grey;
    lamp.name = "lamp";
    lamp.color = {0, 0, 0};
    lamp.emission = {30.0, 30.0, 30.0};
    scene.materials = {grey, lamp};
    Sphere floor;
    floor.center = {0.0, -1e4, 0.0};
    floor.radius = 1e4;
    floor.material = 0;
    scene.spheres.push_back(floor);
    for (const Vec3& at : {Vec3{-150.0, 300.0, 100.0}, Vec3{200.0, 250.0, -50.0}}) {
        Sphere light;
        light.center = at;
        light.radius = 30.0;
        light.material = 1;
        scene.spheres.push_back(light);
    }
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> x(-100.0, 100.0), y(0.5, 200.0), r(0.2, 0.5);
    std::normal_distribution<double> gauss;
    std::vector<Vec3> velocity;
    const std::size_t first_particle = scene.spheres.size();
    for (std::size_t i = 0; i < n; ++i) {
        Sphere s;
        s.center = {x(rng), y(rng), x(rng)};
        s.radius = r(rng);
        s.material = 0;
        scene.spheres.push_back(s);
        Vec3 v{gauss(rng), gauss(rng), gauss(rng)};
        const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (double& c : v) c *= step / length;
        velocity.push_back(v);
    }

    RenderConfig config;
    config.development = orb::bench::development_knobs_or_exit("orb-bvh-refit-benchmark");
    config.width = 320;
    config.height = 240;
    Renderer refitting(scene, config);
    SphereBvh refitted = scene_bvh(scene);
    const double first_cost = bvh_sah_cost(refitted);
    std::printf("spheres=%zu step=%g spp=%d, frame 0: SAH cost %.1f\n", n, step, spp, first_cost);
    std::printf("frame build_s refit_s cost_built cost_refit render_built_s render_refit_s renderer_refitted\n");
    for (int frame = 1; frame <= frames; ++frame) {
        for (std::size_t i = 0; i < n; ++i)
            for (int a = 0; a < 3; ++a) scene.spheres[first_particle + i].center[a] += velocity[i][a];

        auto start = std::chrono::steady_clock::now();
        const SphereBvh built = scene_bvh(scene);
        const double build_seconds = seconds_since(start);
        start = std::chrono::steady_clock::now();
        refit_sphere_bvh(refitted, scene.spheres);
        const double refit_seconds = seconds_since(start);

        Renderer fresh(scene, config);
        start = std::chrono::steady_clock::now();
        fresh.render_pass(spp);
        fresh.read_film();
        const double render_built = seconds_since(start);

        refitting.set_scene(scene);
        start = std::chrono::steady_clock::now();
        refitting.render_pass(spp);
        refitting.read_film();
        const double render_refit = seconds_since(start);

        std::printf("%d %.3f %.3f %.1f %.1f %.3f %.3f %s\n", frame, build_seconds, refit_seconds, bvh_sah_cost(built),
                    bvh_sah_cost(refitted), render_built, render_refit,
                    refitting.last_tree_refitted() ? "refit" : "rebuilt");
    }
}
