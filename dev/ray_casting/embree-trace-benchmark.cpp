// A peer for orb-trace-benchmark: casts the batches it dumps (--dump DIR)
// with Intel Embree 3 (Debian's libembree-dev), on the CPU's threads, so
// that Orb's traversal on PoCL can be set beside a hand-vectorised one on
// the same machine, rays and spheres (docs/design/bvh-traversal.md). Built and run by dev/ray_casting/embree-trace-benchmark.sh; not
// part of Orb's build.
//
//   embree-trace-benchmark DIR [--threads N] [--seconds S] [--split]
//
// --split puts the spheres that Orb keeps outside its tree (the floor, the
// lamps) in a geometry of their own, as Orb does; by default every sphere is
// in one geometry and one tree. Spheres are Embree's RTC_GEOMETRY_TYPE_SPHERE_POINT.
// A ray leaving a sphere starts a little past it (tnear, larger for a huge
// sphere, whose test in Embree rounds to about 1e-7 of its radius) instead
// of naming the sphere it leaves, as Orb's rays do; the answers are then
// compared with Orb's, ray by ray, and the share that differ is printed.

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

struct Ray {  // orb-trace-benchmark's CastRay
    float origin[3];
    std::int32_t self;
    float direction[3];
    std::int32_t light;
};
static_assert(sizeof(Ray) == 32);

struct Hit {  // orb-trace-benchmark's CastHit
    std::int32_t sphere;
    float t;
};

template <class T>
std::vector<T> read_array(const std::string& path)
{
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw std::runtime_error("cannot read " + path);
    const std::streamsize bytes = in.tellg();
    if (bytes % static_cast<std::streamsize>(sizeof(T)) != 0) throw std::runtime_error(path + ": size is not whole records");
    std::vector<T> data(static_cast<std::size_t>(bytes) / sizeof(T));
    in.seekg(0);
    in.read(reinterpret_cast<char*>(data.data()), bytes);
    if (!in) throw std::runtime_error("cannot read " + path);
    return data;
}

struct Sphere {
    float x, y, z, r;
    bool outside;
};

// The scene's spheres as one or two Embree geometries; `slot_of[g][prim]`
// maps an Embree primitive back to Orb's slot.
struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<std::vector<int>> slot_of;
    double build_seconds = 0;

    EmbreeScene(const std::vector<Sphere>& spheres, bool split)
    {
        device = rtcNewDevice(nullptr);
        if (!device) throw std::runtime_error("rtcNewDevice failed");
        scene = rtcNewScene(device);
        const int groups = split ? 2 : 1;
        slot_of.resize(groups);
        const auto start = std::chrono::steady_clock::now();
        for (int g = 0; g < groups; ++g) {
            std::vector<int>& slots = slot_of[g];
            for (std::size_t i = 0; i < spheres.size(); ++i)
                if (spheres[i].r > 0 && (!split || spheres[i].outside == (g == 1))) slots.push_back(static_cast<int>(i));
            if (slots.empty()) continue;
            RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
            auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                         RTC_FORMAT_FLOAT4, 4 * sizeof(float), slots.size()));
            for (std::size_t k = 0; k < slots.size(); ++k) {
                const Sphere& s = spheres[slots[k]];
                vertices[4 * k] = s.x, vertices[4 * k + 1] = s.y, vertices[4 * k + 2] = s.z, vertices[4 * k + 3] = s.r;
            }
            rtcCommitGeometry(geometry);
            rtcAttachGeometryByID(scene, geometry, static_cast<unsigned>(g));
            rtcReleaseGeometry(geometry);
        }
        rtcCommitScene(scene);
        build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    ~EmbreeScene()
    {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
};

// How far past the sphere it leaves a ray starts: far above float rounding
// at these scenes' scales, far below their spheres' sizes; for a sphere
// whose radius is over 100 (the floor of radius 1e5), 1e-5 of its radius.
constexpr float kLeave = 1e-3f;

float leaving_distance(const Ray& r, const std::vector<Sphere>& spheres)
{
    if (r.self < 0) return 0.0f;
    return std::max(kLeave, 1e-5f * spheres.at(static_cast<std::size_t>(r.self)).r);
}

RTCRay embree_ray(const Ray& r, float tnear, float tfar)
{
    RTCRay ray{};
    ray.org_x = r.origin[0], ray.org_y = r.origin[1], ray.org_z = r.origin[2];
    ray.dir_x = r.direction[0], ray.dir_y = r.direction[1], ray.dir_z = r.direction[2];
    ray.tnear = tnear;
    ray.tfar = tfar;
    ray.mask = 0xFFFFFFFFu;
    return ray;
}

// Distance along `r` to the near side of sphere `s` (Orb's lane test), or
// infinity when it misses.
float sphere_distance(const Ray& r, const Sphere& s)
{
    const float ox = r.origin[0] - s.x, oy = r.origin[1] - s.y, oz = r.origin[2] - s.z;
    const float b = ox * r.direction[0] + oy * r.direction[1] + oz * r.direction[2];
    const float fx = ox - b * r.direction[0], fy = oy - b * r.direction[1], fz = oz - b * r.direction[2];
    const float disc = s.r * s.r - (fx * fx + fy * fy + fz * fz);
    if (disc < 0) return INFINITY;
    const float t = -b - std::sqrt(disc);
    return t > 0 ? t : INFINITY;
}

// One batch: closest hits, or shadow rays (occluded before the light).
struct Batch {
    std::vector<Ray> rays;
    std::vector<float> tnear;        // leaving_distance
    std::vector<float> shadow_tfar;  // shadow rays: where the light's surface starts, shortened
    bool shadow = false;
};

void cast_range(const EmbreeScene& es, const Batch& batch, std::size_t begin, std::size_t end, Hit* hits,
                std::int32_t* visible)
{
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t i = begin; i < end; ++i) {
        if (batch.shadow) {
            RTCRay ray = embree_ray(batch.rays[i], batch.tnear[i], batch.shadow_tfar[i]);
            rtcOccluded1(es.scene, &context, &ray);
            if (visible) visible[i] = ray.tfar >= 0 ? 1 : 0;  // Embree sets tfar to -inf when occluded
        } else {
            RTCRayHit rh{};
            rh.ray = embree_ray(batch.rays[i], batch.tnear[i], INFINITY);
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(es.scene, &context, &rh);
            if (hits) {
                const bool hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
                hits[i] = {hit ? es.slot_of[rh.hit.geomID][rh.hit.primID] : -1, rh.ray.tfar};
            }
        }
    }
}

// Casts the batch `times` times on `threads` threads; seconds taken.
double cast(const EmbreeScene& es, const Batch& batch, int threads, int times, Hit* hits, std::int32_t* visible)
{
    const auto start = std::chrono::steady_clock::now();
    for (int round = 0; round < times; ++round) {
        std::vector<std::thread> pool;
        // Interleaved chunks so that both threads get rays of every kind.
        constexpr std::size_t kChunk = 1024;
        std::atomic<std::size_t> next{0};
        for (int t = 0; t < threads; ++t)
            pool.emplace_back([&] {
                for (;;) {
                    const std::size_t begin = next.fetch_add(kChunk);
                    if (begin >= batch.rays.size()) return;
                    cast_range(es, batch, begin, std::min(batch.rays.size(), begin + kChunk), hits, visible);
                }
            });
        for (std::thread& t : pool) t.join();
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv)
{
    try {
        if (argc < 2) throw std::runtime_error("usage: embree-trace-benchmark DIR [--threads N] [--seconds S] [--split]");
        const std::string dir = argv[1];
        int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
        double seconds = 2.0;
        bool split = false;
        for (int i = 2; i < argc; ++i) {
            const std::string flag = argv[i];
            if (flag == "--split") split = true;
            else if (flag == "--threads" && i + 1 < argc) threads = std::stoi(argv[++i]);
            else if (flag == "--seconds" && i + 1 < argc) seconds = std::stod(argv[++i]);
            else throw std::runtime_error("unknown option " + flag);
        }
        const std::vector<float> raw = read_array<float>(dir + "/spheres.f32");
        std::vector<Sphere> spheres;
        for (std::size_t i = 0; i + 5 <= raw.size(); i += 5)
            spheres.push_back({raw[i], raw[i + 1], raw[i + 2], raw[i + 3], raw[i + 4] != 0.0f});
        const EmbreeScene es(spheres, split);
        const auto real_spheres = std::count_if(spheres.begin(), spheres.end(), [](const Sphere& s) { return s.r > 0; });
        std::printf("embree=%s threads=%d spheres=%td split=%d build_seconds=%.3f\n", RTC_VERSION_STRING, threads,
                    real_spheres, split ? 1 : 0, es.build_seconds);

        for (const char* name : {"camera", "bounce", "shadow"}) {
            Batch batch;
            batch.rays = read_array<Ray>(dir + "/" + name + ".rays");
            batch.shadow = std::string(name) == "shadow";
            for (const Ray& r : batch.rays) batch.tnear.push_back(leaving_distance(r, spheres));
            if (batch.shadow)
                for (const Ray& r : batch.rays)
                    batch.shadow_tfar.push_back(sphere_distance(r, spheres.at(static_cast<std::size_t>(r.light))) *
                                                (1.0f - kLeave));
            // Agreement with Orb's answers; this first cast also warms up
            // and sets how many casts fill `seconds`.
            std::size_t differ = 0;
            double once = 0;
            if (batch.shadow) {
                const std::vector<std::int32_t> orb = read_array<std::int32_t>(dir + "/" + name + ".hits");
                std::vector<std::int32_t> ours(batch.rays.size());
                once = cast(es, batch, threads, 1, nullptr, ours.data());
                for (std::size_t i = 0; i < ours.size(); ++i) differ += (ours[i] != 0) != (orb.at(i) != 0);
            } else {
                const std::vector<Hit> orb = read_array<Hit>(dir + "/" + name + ".hits");
                std::vector<Hit> ours(batch.rays.size());
                once = cast(es, batch, threads, 1, ours.data(), nullptr);
                for (std::size_t i = 0; i < ours.size(); ++i) differ += ours[i].sphere != orb.at(i).sphere;
            }
            const int times = std::max(1, static_cast<int>(seconds / std::max(once, 1e-6)));
            const double rate = static_cast<double>(batch.rays.size()) * times / cast(es, batch, threads, times, nullptr, nullptr);
            std::printf("%s rays: %zu rays, %.4g rays/s, answers differing from Orb's: %zu (%.4f%%)\n", name,
                        batch.rays.size(), rate, differ, 100.0 * static_cast<double>(differ) / std::max<std::size_t>(1, batch.rays.size()));
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "embree-trace-benchmark: error: %s\n", error.what());
        return 1;
    }
    return 0;
}
