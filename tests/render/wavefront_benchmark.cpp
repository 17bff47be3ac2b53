// Not a test: the wavefront prototype (kernels/wavefront.cl,
// librender/src/wavefront_renderer.h) against render_pass, side by side in
// one process on one device, for deciding whether a wavefront design beats
// the megakernel (docs/performance.md, "A wavefront renderer, measured").
//
//   build/bin/orb-wavefront-benchmark SCENE [--device SEL] [--width W] [--height H] [--seconds S]
//       [--rounds R] [--paths-per-pixel K] [--sampler sobol|independent] [--options "CL OPTIONS"]
//
// Each round times render_pass (only the beauty layer's channels built, as
// `orb-render --passes beauty`) and then the wavefront renderer for S
// seconds each (default 2, 1920x1080, 2 rounds), after a warm-up, and
// prints both in samples per second. Both render the same samples of the
// same estimator (global mode, the scene's depth), so the mean radiance of
// the two images, printed too, must agree within noise.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "benchmark_support.h"
#include "device_renderer.h"
#include "orb/render/device.h"
#include "orb/render/film.h"
#include "scene_layout.h"
#include "wavefront_renderer.h"

using namespace orb;
using namespace orb::render;

namespace {

using Clock = std::chrono::steady_clock;

using bench::seconds_since;

struct Timed {
    double samples_per_second = 0;
    double mean_radiance = 0;  // over pixels and the three components
};

double mean_of(const std::vector<float>& sums, std::uint64_t samples)
{
    double total = 0;
    for (float v : sums) total += v;
    return total / static_cast<double>(sums.size()) / static_cast<double>(samples);
}

// `run(first, count)` renders `count` units of `samples_per_unit` samples
// per pixel from sample `first` on and waits. Units per call are chosen
// from a warm-up so that a call lasts about 0.1 s, as orb-render's passes.
template <typename Run>
std::pair<std::uint64_t, double> time_units(Run run, int samples_per_unit, std::uint64_t pixels, double seconds)
{
    auto start = Clock::now();
    run(0, 1);
    const double once = seconds_since(start);
    const int per_call = std::max(1, static_cast<int>(0.1 / std::max(once, 1e-6)));
    std::uint64_t units = 1;
    start = Clock::now();
    std::uint64_t timed_units = 0;
    while (seconds_since(start) < seconds) {
        run(units * samples_per_unit, per_call);
        units += per_call;
        timed_units += per_call;
    }
    const double elapsed = seconds_since(start);
    return {units * samples_per_unit, static_cast<double>(timed_units * samples_per_unit * pixels) / elapsed};
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::cerr << "usage: orb-wavefront-benchmark SCENE [--device SEL] [--width W] [--height H] [--seconds S] "
                     "[--rounds R] [--paths-per-pixel K] [--sampler sobol|independent] [--options \"CL OPTIONS\"]\n";
        return 2;
    }
    try {
        std::string device_selector, extra_options;
        int width = 1920, height = 1080, rounds = 2, paths_per_pixel = 1;
        double seconds = 2.0;
        SamplerKind sampler = SamplerKind::Sobol;
        for (int i = 2; i + 1 < argc; i += 2) {
            const std::string flag = argv[i], value = argv[i + 1];
            if (flag == "--device") device_selector = value;
            else if (flag == "--width") width = std::stoi(value);
            else if (flag == "--height") height = std::stoi(value);
            else if (flag == "--seconds") seconds = std::stod(value);
            else if (flag == "--rounds") rounds = std::stoi(value);
            else if (flag == "--paths-per-pixel") paths_per_pixel = std::stoi(value);
            else if (flag == "--options") extra_options = value;
            else if (flag == "--sampler" && (value == "sobol" || value == "independent"))
                sampler = value == "sobol" ? SamplerKind::Sobol : SamplerKind::Independent;
            else throw std::runtime_error("unknown option or value: " + flag + " " + value);
        }
        const Scene scene = bench::import_scene_file(argv[1]);
        const SceneLayout layout = layout_scene(scene);
        const device::CameraParams camera = layout_camera(scene.camera, width, height);

        RenderConfig config;
        config.width = width;
        config.height = height;
        config.max_depth = scene.render.max_depth;
        config.sampler = sampler;
        config.film_channels = film::channels_for(std::array{film::Layer::Beauty});
        const DeviceInfo device = choose_device(device_selector);
        const std::shared_ptr<DeviceSession> session = DeviceSession::open(device, {});
        DeviceRenderer megakernel(session, config);
        megakernel.set_scene(layout, camera);
        WavefrontRenderer wavefront(session, layout, camera, config, paths_per_pixel, extra_options);
        const std::uint64_t pixels = static_cast<std::uint64_t>(width) * height;
        std::printf("device=%s (%s) spheres=%zu tree_nodes=%d %dx%d paths_per_pixel=%d path_state_bytes=%llu\n",
                    device.name.c_str(), device.platform.c_str(), scene.spheres.size(), layout.counts.bvh_node_count,
                    width, height, paths_per_pixel, static_cast<unsigned long long>(wavefront.path_state_bytes()));

        for (int round = 1; round <= rounds; ++round) {
            megakernel.clear_film();
            const auto [mega_samples, mega_rate] = time_units(
                [&](std::uint64_t first, int count) {
                    megakernel.enqueue(first, count);
                    megakernel.wait();
                },
                1, pixels, seconds);
            Film film;
            film.resize(width, height);
            megakernel.read_film(film);

            wavefront.clear();
            const auto [wave_samples, wave_rate] = time_units(
                [&](std::uint64_t first, int count) {
                    wavefront.enqueue(first, count);
                    wavefront.finish();
                },
                paths_per_pixel, pixels, seconds);
            std::printf("round %d: megakernel %.4g samples/s (mean radiance %.5f over %llu spp), wavefront %.4g "
                        "samples/s (mean radiance %.5f over %llu spp), wavefront/megakernel %.3f\n",
                        round, mega_rate, mean_of(film.radiance, mega_samples),
                        static_cast<unsigned long long>(mega_samples), wave_rate,
                        mean_of(wavefront.radiance_sums(), wave_samples), static_cast<unsigned long long>(wave_samples),
                        wave_rate / mega_rate);
            std::fflush(stdout);
        }
        // Where a wave's time goes: each launch waited for (so slower than
        // the rates above), averaged over a few waves.
        constexpr int kProfiledWaves = 4;
        WavefrontRenderer::WaveProfile total;
        for (int w = 0; w < kProfiledWaves; ++w) {
            const WavefrontRenderer::WaveProfile p =
                wavefront.profile_wave(static_cast<std::uint64_t>(w) * wavefront.paths_per_pixel());
            total.begin += p.begin, total.intersect += p.intersect, total.shade += p.shade, total.shadow += p.shadow;
            if (w == 0) total.paths = p.paths, total.shadow_rays = p.shadow_rays;
        }
        const double samples = static_cast<double>(pixels) * wavefront.paths_per_pixel() * kProfiledWaves;
        std::printf("profiled waves, ns per sample: begin %.3f, intersect %.3f, shade %.3f, shadow %.3f\n",
                    1e9 * total.begin / samples, 1e9 * total.intersect / samples, 1e9 * total.shade / samples,
                    1e9 * total.shadow / samples);
        const double wave_paths = static_cast<double>(pixels) * wavefront.paths_per_pixel();
        std::printf("rays per sample (first wave), closest hits by event:");
        for (int n : total.paths) std::printf(" %.3f", n / wave_paths);
        std::printf("; shadow rays by event:");
        for (int n : total.shadow_rays) std::printf(" %.3f", n / wave_paths);
        std::printf("\n");
    } catch (const std::exception& error) {
        std::cerr << "orb-wavefront-benchmark: error: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
