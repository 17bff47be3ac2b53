// Not a test: rays per second of ray casting alone on a device, for deciding
// whether a wavefront renderer would pay (docs/design/bvh-traversal.md).
// A wavefront design casts each bounce's rays in
// a kernel of their own, which carries no path state and so needs few
// registers; this measures that kernel's part, with the traversal
// render_pass uses (trace_rays, dev/ray_casting/ray_caster.h).
//
//   build/bin/orb-trace-benchmark SCENE [--device SEL] [--width W] [--height H] [--seconds S] [--dump DIR]
//
// Three batches, each cast repeatedly for S seconds (default 2) after one
// warm-up cast:
//  - camera rays: one pinhole ray through each pixel centre (default 1920x1080);
//  - bounce rays: from each camera ray's hit, a cosine-distributed direction
//    about the normal (a diffuse bounce, leaving that sphere);
//  - shadow rays: from each hit to a random point on a random light.
// The bounce and shadow rays are the kind a path's later vertices cast; the
// camera rays are the most coherent a renderer casts. Bounce and shadow rays
// are cast three ways: in pixel order (as a wavefront renderer's compacted
// queue holds them), sorted by direction octant and then by the Morton code
// of the origin (what a wavefront renderer that sorts its rays would cast;
// the sort's own cost is not counted), and shuffled (lanes holding unrelated
// rays, close to a megakernel's warps after a few bounces).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "benchmark_support.h"
#include "orb/render/device.h"
#include "ray_caster.h"
#include "scene_layout.h"

using namespace orb;
using namespace orb::render;

namespace {

struct V {
    float x, y, z;
};
V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V operator*(float s, V a) { return {s * a.x, s * a.y, s * a.z}; }
float dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V unit(V a) { return (1.0f / std::sqrt(dot(a, a))) * a; }
V cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V xyz(const device::float4& v) { return {v.x, v.y, v.z}; }

CastRay make_ray(V o, V d, int self, int light = -1)
{
    CastRay ray;
    ray.origin[0] = o.x, ray.origin[1] = o.y, ray.origin[2] = o.z;
    ray.direction[0] = d.x, ray.direction[1] = d.y, ray.direction[2] = d.z;
    ray.self = self;
    ray.light = light;
    return ray;
}

// Rays per second of `rays` cast for about `seconds`, after a warm-up cast.
double rays_per_second(RayCaster& caster, const std::vector<CastRay>& rays, bool shadow, double seconds)
{
    caster.load(rays);
    const double once = caster.cast_loaded(shadow, 1);
    const int times = std::max(1, static_cast<int>(seconds / std::max(once, 1e-6)));
    return static_cast<double>(rays.size()) * times / caster.cast_loaded(shadow, times);
}

// 10 bits per axis interleaved: nearby points get nearby codes.
std::uint32_t morton3(float x, float y, float z)
{
    const auto spread = [](float f) {
        std::uint32_t v = static_cast<std::uint32_t>(std::clamp(f, 0.0f, 1.0f) * 1023.0f);
        v = (v | (v << 16)) & 0x030000FFu;
        v = (v | (v << 8)) & 0x0300F00Fu;
        v = (v | (v << 4)) & 0x030C30C3u;
        v = (v | (v << 2)) & 0x09249249u;
        return v;
    };
    return (spread(x) << 2) | (spread(y) << 1) | spread(z);
}

// The rays ordered by direction octant, then by the Morton code of their
// origin within the origins' bounding box.
std::vector<CastRay> sorted_by_octant_and_origin(const std::vector<CastRay>& rays)
{
    V lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
    for (const CastRay& r : rays) {
        lo = {std::min(lo.x, r.origin[0]), std::min(lo.y, r.origin[1]), std::min(lo.z, r.origin[2])};
        hi = {std::max(hi.x, r.origin[0]), std::max(hi.y, r.origin[1]), std::max(hi.z, r.origin[2])};
    }
    const V extent = hi - lo;
    const float scale = 1.0f / std::max({extent.x, extent.y, extent.z, 1e-30f});
    std::vector<std::pair<std::uint64_t, std::size_t>> keys;
    keys.reserve(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const CastRay& r = rays[i];
        const std::uint64_t octant = (r.direction[0] < 0 ? 4u : 0u) | (r.direction[1] < 0 ? 2u : 0u) |
                                     (r.direction[2] < 0 ? 1u : 0u);
        const std::uint32_t code = morton3((r.origin[0] - lo.x) * scale, (r.origin[1] - lo.y) * scale,
                                           (r.origin[2] - lo.z) * scale);
        keys.push_back({(octant << 32) | code, i});
    }
    std::sort(keys.begin(), keys.end());
    std::vector<CastRay> sorted;
    sorted.reserve(rays.size());
    for (const auto& key : keys) sorted.push_back(rays[key.second]);
    return sorted;
}

// --dump DIR: the spheres and the three batches with Orb's answers, for a
// peer to cast the same rays (embree-trace-benchmark.sh beside this). Raw
// little-endian arrays, no header:
//   spheres.f32  five floats per sphere slot: centre xyz, radius, and 1 for
//                a sphere outside the tree (the floor, the lamps) else 0;
//                padding slots have radius 0
//   NAME.rays    CastRay records (32 bytes: origin, self, direction, light)
//   NAME.hits    camera and bounce: CastHit records (sphere, t); shadow:
//                one int32 per ray, 1 when the light is visible
void write_raw(const std::string& path, const void* data, std::size_t bytes)
{
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw std::runtime_error("cannot write " + path);
    const bool ok = std::fwrite(data, 1, bytes, file) == bytes;
    if (std::fclose(file) != 0 || !ok) throw std::runtime_error("cannot write " + path);
}

// The camera rays' hits are the ones the bounce and shadow rays were made
// from; the other two batches are cast here for their answers.
void dump_batches(const std::string& dir, const SceneLayout& layout, RayCaster& caster,
                  const std::vector<CastRay>& camera_rays, const std::vector<CastHit>& camera_hits,
                  const std::vector<CastRay>& bounce_rays, const std::vector<CastRay>& shadow_rays)
{
    std::vector<float> spheres;
    const std::size_t outside_slots = 4 * static_cast<std::size_t>(layout.counts.outside_packet_count);
    for (std::size_t i = 0; i < layout.tables.spheres.size(); ++i) {
        const device::float4 s = layout.tables.spheres[i].centre_radius;
        spheres.insert(spheres.end(), {s.x, s.y, s.z, s.w, i < outside_slots ? 1.0f : 0.0f});
    }
    write_raw(dir + "/spheres.f32", spheres.data(), spheres.size() * sizeof(float));
    const auto write_rays = [&](const char* name, const std::vector<CastRay>& rays) {
        write_raw(dir + "/" + name + ".rays", rays.data(), rays.size() * sizeof(CastRay));
    };
    write_rays("camera", camera_rays);
    write_raw(dir + "/camera.hits", camera_hits.data(), camera_hits.size() * sizeof(CastHit));
    write_rays("bounce", bounce_rays);
    const std::vector<CastHit> bounce_hits = caster.closest(bounce_rays);
    write_raw(dir + "/bounce.hits", bounce_hits.data(), bounce_hits.size() * sizeof(CastHit));
    write_rays("shadow", shadow_rays);
    const std::vector<bool> visible = caster.visible(shadow_rays);
    const std::vector<std::int32_t> flags(visible.begin(), visible.end());
    write_raw(dir + "/shadow.hits", flags.data(), flags.size() * sizeof(std::int32_t));
}

std::vector<CastRay> shuffled(std::vector<CastRay> rays)
{
    std::mt19937 rng(7);
    std::shuffle(rays.begin(), rays.end(), rng);
    return rays;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::cerr << "usage: orb-trace-benchmark SCENE [--device SEL] [--width W] [--height H] [--seconds S] [--dump DIR]\n";
        return 2;
    }
    try {
        std::string device_selector, dump_dir;
        int width = 1920, height = 1080;
        double seconds = 2.0;
        for (int i = 2; i + 1 < argc; i += 2) {
            const std::string flag = argv[i], value = argv[i + 1];
            if (flag == "--device") device_selector = value;
            else if (flag == "--width") width = std::stoi(value);
            else if (flag == "--height") height = std::stoi(value);
            else if (flag == "--seconds") seconds = std::stod(value);
            else if (flag == "--dump") dump_dir = value;
            else throw std::runtime_error("unknown option " + flag);
        }
        const Scene scene = bench::import_scene_file(argv[1]);
        const SceneLayout layout = layout_scene(scene);
        const device::CameraParams camera = layout_camera(scene.camera, width, height);

        // The development knobs as orb-render reads them: the kernel folder,
        // the build log, and ORB_CL_OPTIONS added to trace_rays's options.
        const render::DevelopmentKnobs knobs = bench::development_knobs_or_exit("orb-trace-benchmark");
        const DeviceInfo device = choose_device(device_selector);
        RayCaster caster(DeviceSession::open(device, {knobs.kernel_dir, true, knobs.show_build_log}), layout,
                         knobs.cl_options);
        std::cout << "device=" << device.name << " (" << device.platform << ") spheres=" << scene.spheres.size()
                  << " tree_nodes=" << layout.counts.bvh_node_count << "\n";

        // Camera rays through the pixel centres (camera.cl's pinhole ray).
        std::vector<CastRay> camera_rays;
        camera_rays.reserve(static_cast<std::size_t>(width) * height);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const float ndc_x = 2.0f * (x + 0.5f) / width - 1.0f, ndc_y = 1.0f - 2.0f * (y + 0.5f) / height;
                const V d = unit(xyz(camera.forward) + (ndc_x * camera.half_width) * xyz(camera.right) +
                                 (ndc_y * camera.half_height) * xyz(camera.up));
                camera_rays.push_back(make_ray(xyz(camera.origin), d, -1));
            }
        const std::vector<CastHit> hits = caster.closest(camera_rays);

        // Bounce and shadow rays from the hits.
        std::vector<int> lights;
        for (const device::LightRecord& light : layout.tables.lights)
            if (light.sphere >= 0 && light.probability > 0.0f) lights.push_back(light.sphere);
        std::mt19937 rng(1);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        std::vector<CastRay> bounce_rays, shadow_rays;
        for (std::size_t i = 0; i < hits.size(); ++i) {
            if (hits[i].sphere < 0) continue;
            const CastRay& ray = camera_rays[i];
            const V o{ray.origin[0], ray.origin[1], ray.origin[2]}, d{ray.direction[0], ray.direction[1], ray.direction[2]};
            const V p = o + hits[i].t * d;
            const device::float4 sphere = layout.tables.spheres[hits[i].sphere].centre_radius;
            V n = unit(p - xyz(sphere));
            if (dot(n, d) > 0.0f) n = -1.0f * n;
            const V t = unit(cross(std::fabs(n.x) > 0.5f ? V{0, 1, 0} : V{1, 0, 0}, n)), b = cross(n, t);
            const float r = std::sqrt(u(rng)), phi = 6.2831853f * u(rng);
            const V w = (r * std::cos(phi)) * t + (r * std::sin(phi)) * b + std::sqrt(std::max(0.0f, 1.0f - r * r)) * n;
            bounce_rays.push_back(make_ray(p, unit(w), hits[i].sphere));
            if (lights.empty()) continue;
            const int light = lights[std::min(lights.size() - 1, static_cast<std::size_t>(u(rng) * lights.size()))];
            const device::float4 lamp = layout.tables.spheres[light].centre_radius;
            const float z = 1.0f - 2.0f * u(rng), a = 6.2831853f * u(rng), s = std::sqrt(std::max(0.0f, 1.0f - z * z));
            const V target = xyz(lamp) + lamp.w * V{s * std::cos(a), s * std::sin(a), z};
            shadow_rays.push_back(make_ray(p, unit(target - p), hits[i].sphere, light));
        }

        if (!dump_dir.empty())
            dump_batches(dump_dir, layout, caster, camera_rays, hits, bounce_rays, shadow_rays);

        const auto report = [&](const char* name, const std::vector<CastRay>& rays, bool shadow) {
            if (rays.empty()) {
                std::cout << name << ": none\n";
                return;
            }
            const double rate = rays_per_second(caster, rays, shadow, seconds);
            std::printf("%s: %zu rays, %.4g rays/s\n", name, rays.size(), rate);
        };
        // One bounce ray per camera ray that hit a sphere.
        std::printf("camera rays hitting a sphere: %.3f\n", static_cast<double>(bounce_rays.size()) / camera_rays.size());
        report("camera rays", camera_rays, false);
        report("bounce rays", bounce_rays, false);
        report("shadow rays", shadow_rays, true);
        report("bounce rays sorted", sorted_by_octant_and_origin(bounce_rays), false);
        report("shadow rays sorted", sorted_by_octant_and_origin(shadow_rays), true);
        report("bounce rays shuffled", shuffled(bounce_rays), false);
        report("shadow rays shuffled", shuffled(shadow_rays), true);
    } catch (const std::exception& error) {
        std::cerr << "orb-trace-benchmark: error: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
