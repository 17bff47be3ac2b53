#include "render_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "device_renderer.h"
#include "orb/film/pixel_error.h"
#include "orb/import/scn.h"
#include "scene_layout.h"

namespace orb::render::test {

std::uint32_t add_material(Scene& scene, MaterialType type, Vec3 color, Vec3 emission, double ior)
{
    Material m;
    m.name = std::string("m").append(std::to_string(scene.materials.size()));  // not "m" + ...: GCC 12's false -Wrestrict
    m.type = type;
    m.color = color;
    m.emission = emission;
    m.ior = ior;
    scene.materials.push_back(m);
    return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

int add_sphere(Scene& scene, Vec3 centre, double radius, std::uint32_t material)
{
    Sphere s;
    s.name = std::string("s").append(std::to_string(scene.spheres.size()));
    s.center = centre;
    s.radius = radius;
    s.material = material;
    scene.spheres.push_back(s);
    return static_cast<int>(scene.spheres.size() - 1);
}

RenderConfig small_config(int width, int height, std::uint64_t seed, int max_depth, IntegratorMode mode)
{
    RenderConfig config;
    config.width = width;
    config.height = height;
    config.seed = seed;
    config.max_depth = max_depth;
    config.mode = mode;
    return config;
}

Scene every_branch_scene()
{
    Scene scene;
    scene.camera.position = {0.0, 2.0, 7.0};
    scene.camera.target = {0.0, 0.8, 0.0};
    scene.camera.vfov_deg = 45.0;
    scene.camera.aperture = 0.1;
    scene.camera.focus_distance = 7.0;
    const auto floor = add_material(scene, MaterialType::Diffuse, {0.7, 0.7, 0.7});
    const auto red = add_material(scene, MaterialType::Diffuse, {0.8, 0.2, 0.2});
    const auto mirror = add_material(scene, MaterialType::Mirror, {0.9, 0.9, 0.9});
    const auto glass = add_material(scene, MaterialType::Dielectric, {1.0, 0.95, 0.9}, {0, 0, 0}, 1.5);
    add_sphere(scene, {0.0, -1e4, 0.0}, 1e4, floor);
    add_sphere(scene, {-1.6, 0.7, 0.0}, 0.7, red);
    add_sphere(scene, {0.0, 0.7, -0.5}, 0.7, mirror);
    add_sphere(scene, {1.6, 0.7, 0.4}, 0.7, glass);
    add_sphere(scene, {-2.0, 4.0, 1.0}, 0.4, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {20, 18, 16}));
    add_sphere(scene, {2.5, 3.0, -1.0}, 0.3, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {4, 6, 8}));
    add_sphere(scene, {0.0, 5.0, -2.0}, 0.8, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {1, 1, 1}));
    return scene;
}

Film render(const Scene& scene, const RenderConfig& config, const std::vector<int>& passes)
{
    Renderer renderer(scene, config);
    for (int samples : passes) renderer.render_pass(samples);
    return renderer.read_film();
}

Film render_with_cl_options(const Scene& scene, const RenderConfig& config, const std::vector<int>& passes,
                            const char* cl_options)
{
    RenderConfig variant = config;
    if (cl_options) variant.development.cl_options = cl_options;
    return render(scene, variant, passes);
}

device::KernelFeatures gpu_traversal(const Scene& scene, int warp_vote)
{
    DeviceInfo gpu;
    gpu.platform = "a GPU's";
    gpu.is_gpu = true;
    device::KernelFeatures features;
    choose_traversal(gpu, layout_scene(scene), features);
    features.warp_vote = warp_vote;
    return features;
}

Film render_with_simd_lanes(const Scene& scene, const RenderConfig& config, const std::vector<int>& passes,
                            const char* lanes)
{
    RenderConfig variant = config;
    if (lanes) variant.development.simd_lanes = std::stoi(lanes);
    return render(scene, variant, passes);
}

Scene load_scene_file(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return parse_scn(text.str(), path);
}

PixelStatistics radiance_statistics(const Film& film, const std::vector<std::size_t>& pixels, int channel)
{
    PixelStatistics stats;
    if (pixels.empty()) throw std::invalid_argument("need pixels");
    double sum_of_means = 0, sum_of_variances = 0;
    for (std::size_t p : pixels) {
        const double n = film::pixel_samples(film, p);  // each pixel's own count (adaptive sampling)
        if (n < 2) throw std::invalid_argument("need at least two samples in every pixel");
        const double sum = film::sum_value(film::Units::Fixed, film.radiance[p * 3 + channel]);
        const double sum_sq = film::sum_value(film::Units::Fixed, film.radiance_sq[p * 3 + channel]);
        const double mean = sum / n;
        const double sample_variance = std::max(0.0, (sum_sq - n * mean * mean) / (n - 1));
        sum_of_means += mean;
        sum_of_variances += sample_variance / n;  // variance of this pixel's mean
    }
    const double count = static_cast<double>(pixels.size());
    stats.mean = sum_of_means / count;
    stats.standard_error = std::sqrt(sum_of_variances) / count;
    stats.pixels = pixels.size();
    return stats;
}

std::vector<std::size_t> interior_pixels_of(const Film& film, int id)
{
    std::vector<std::size_t> out;
    const auto is = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < film.width && y < film.height &&
               film.object_id[static_cast<std::size_t>(y) * film.width + x] == static_cast<float>(id);
    };
    for (int y = 0; y < film.height; ++y)
        for (int x = 0; x < film.width; ++x) {
            bool interior = true;
            for (int dy = -1; dy <= 1 && interior; ++dy)
                for (int dx = -1; dx <= 1 && interior; ++dx) interior = is(x + dx, y + dy);
            if (interior) out.push_back(static_cast<std::size_t>(y) * film.width + x);
        }
    return out;
}

std::vector<std::size_t> all_pixels(const Film& film)
{
    std::vector<std::size_t> out(film.pixel_count());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = i;
    return out;
}

std::vector<double> sum_values(const Film& film, film::Channel channel)
{
    const std::vector<film::Sum>& sums = film.sums(channel);
    std::vector<double> values(sums.size());
    for (std::size_t i = 0; i < sums.size(); ++i) values[i] = film::sum_value(film::info(channel).units, sums[i]);
    return values;
}

std::vector<std::byte> channel_bytes(const Film& film, film::Channel channel)
{
    const std::span<const std::byte> bytes = film.bytes(channel);
    return {bytes.begin(), bytes.end()};
}

void fill_channel(Film& film, film::Channel channel, double value)
{
    if (film::info(channel).accumulation == film::Accumulation::Sum) {
        std::vector<film::Sum>& sums = film.sums(channel);
        std::fill(sums.begin(), sums.end(), static_cast<film::Sum>(value));
    } else {
        std::vector<float>& values = film.values(channel);
        std::fill(values.begin(), values.end(), static_cast<float>(value));
    }
}

bool channel_is_clear(const Film& film, film::Channel channel)
{
    const film::ChannelInfo& info = film::info(channel);
    if (info.accumulation == film::Accumulation::Sum) {
        const std::vector<film::Sum>& sums = film.sums(channel);
        return std::all_of(sums.begin(), sums.end(), [](film::Sum s) { return s == 0; });
    }
    const std::vector<float>& values = film.values(channel);
    return std::all_of(values.begin(), values.end(), [&](float v) { return v == info.clear; });
}

void expect_same_films(const Film& a, const Film& b)
{
    ASSERT_EQ(a.samples_per_pixel, b.samples_per_pixel);
    EXPECT_EQ(a.held_ranges(), b.held_ranges());
    for (const film::ChannelInfo& info : film::kChannels) {
        if (info.accumulation == film::Accumulation::CentreRay) {
            EXPECT_EQ(a.values(info.channel), b.values(info.channel)) << info.name;
            continue;
        }
        const std::vector<film::Sum>& x = a.sums(info.channel);
        const std::vector<film::Sum>& y = b.sums(info.channel);
        ASSERT_EQ(x.size(), y.size()) << info.name;
        std::size_t differing = 0, first = 0;
        for (std::size_t i = 0; i < x.size(); ++i)
            if (x[i] != y[i] && differing++ == 0) first = i;
        EXPECT_EQ(differing, 0u) << info.name << ": " << differing << " sums differ, the first [" << first << "] "
                                 << (differing ? x[first] : 0) << " against " << (differing ? y[first] : 0);
    }
}

void expect_same_films_up_to_rounding(const Film& a, const Film& b)
{
    ASSERT_EQ(a.samples_per_pixel, b.samples_per_pixel);
    const std::uint64_t n = a.samples_per_pixel;
    const double relative = static_cast<double>(n) * std::ldexp(1.0, -24);
    for (const film::ChannelInfo& info : film::kChannels) {
        if (info.accumulation == film::Accumulation::CentreRay) {
            EXPECT_EQ(a.values(info.channel), b.values(info.channel)) << info.name;
            continue;
        }
        // Normals are unit vectors, whose components cancel in the sum.
        const double bound = info.stored_as == film::StoredAs::UnitVector ? static_cast<double>(n) : 0.0;
        const std::vector<double> x = sum_values(a, info.channel), y = sum_values(b, info.channel);
        ASSERT_EQ(x.size(), y.size()) << info.name;
        const double units = static_cast<double>(n) * film::unit_value(info.units);
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double magnitude = std::max({bound, std::abs(x[i]), std::abs(y[i])});
            ASSERT_NEAR(x[i], y[i], relative * magnitude + units) << info.name << " [" << i << "]";
        }
    }
}

void expect_mostly_same_paths(const std::vector<double>& a, const std::vector<double>& b, const std::string& what)
{
    ASSERT_EQ(a.size(), b.size()) << what;
    std::size_t apart = 0;  // differ by more than the same path's rounding
    double sum = 0, sum_sq = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double d = static_cast<double>(a[i]) - static_cast<double>(b[i]);
        // The same path in both kernels: its single-precision arithmetic over up
        // to seven vertices rounds differently by 1e-6 to 1e-4 of the value
        // (measured on the SIMD kernel's test scenes); a path that took another
        // branch moves its pixel by its whole contribution, mostly 1e-2 and more.
        const double same_path = 1e-3 * std::max({1e-3, std::fabs(static_cast<double>(a[i])),
                                                  std::fabs(static_cast<double>(b[i]))});
        apart += std::fabs(d) > same_path;
        sum += d;
        sum_sq += d * d;
    }
    const double n = static_cast<double>(a.size());
    const double mean_difference = sum / n;
    const double standard_error = std::sqrt(std::max(0.0, sum_sq / n - mean_difference * mean_difference) / (n - 1));
    constexpr double kSigmas = 4.0;
    // A path that leaves the other kernel's path changes its pixel; most do not.
    EXPECT_LE(apart, a.size() / 10) << what << ": " << apart << " of " << a.size() << " apart";
    EXPECT_LE(std::fabs(mean_difference), kSigmas * standard_error + 1e-7)
        << what << ": mean difference " << mean_difference << ", standard error " << standard_error;
}

}  // namespace orb::render::test
