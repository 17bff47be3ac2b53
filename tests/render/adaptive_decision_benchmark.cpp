// orb-adaptive-decision-benchmark: milliseconds one decision of adaptive
// sampling takes on the same film, on the host (the film read back,
// libfilm's estimate, stopping and neighbour rules, the list uploaded: what
// AdaptiveSampler does without a device decision) and on the device
// (Renderer::decide_on_device), side by side in one run; and whether the two
// decided the same. Each decision starts from every pixel active (a first
// decision, the largest). Usage:
//   orb-adaptive-decision-benchmark SCENE [--width W] [--height H] [--spp N]
//                                   [--noise-threshold T] [--repeats N] [--device SEL]
#include <algorithm>
#include <chrono>
#include <iostream>
#include <numeric>
#include <string>
#include <vector>

#include "benchmark_support.h"
#include "orb/film/pixel_error.h"
#include "orb/film/stopping_rule.h"
#include "orb/render/renderer.h"

namespace {

struct Timing {
    double mean_ms = 0;
    double min_ms = 0;
};

// `reset` (untimed), then `step` (timed), `repeats` times.
template <typename Reset, typename Step>
Timing time_repeats(int repeats, Reset reset, Step step)
{
    std::vector<double> ms;
    for (int i = 0; i < repeats; ++i) {
        reset();
        const auto start = std::chrono::steady_clock::now();
        step();
        ms.push_back(1000.0 * orb::bench::seconds_since(start));
    }
    return {std::accumulate(ms.begin(), ms.end(), 0.0) / repeats, *std::min_element(ms.begin(), ms.end())};
}

std::ostream& operator<<(std::ostream& out, const Timing& t)
{
    return out << t.mean_ms << " (min " << t.min_ms << ")";
}

}  // namespace

int main(int argc, char** argv)
{
    using namespace orb::render;
    if (argc < 2) {
        std::cerr << "usage: orb-adaptive-decision-benchmark SCENE [--width W] [--height H] [--spp N] "
                     "[--noise-threshold T] [--repeats N] [--device SEL]\n";
        return 2;
    }
    try {
        const orb::Scene scene = orb::bench::import_scene_file(argv[1]);
        RenderConfig config;
        config.development = orb::bench::development_knobs_or_exit("orb-adaptive-decision-benchmark");
        if (!config.development.device_decisions) config.development.device_decisions = true;  // CPU devices too
        config.width = 1920;
        config.height = 1080;
        config.adaptive = true;
        config.film_channels = orb::film::channel_bit(orb::film::Channel::radiance) |
                               orb::film::channel_bit(orb::film::Channel::radiance_sq) |
                               orb::film::channel_bit(orb::film::Channel::sample_count);
        int spp = 16, repeats = 5;
        double threshold = 0.05;
        for (int i = 2; i + 1 < argc; i += 2) {
            const std::string flag = argv[i], value = argv[i + 1];
            if (flag == "--width") config.width = std::stoi(value);
            else if (flag == "--height") config.height = std::stoi(value);
            else if (flag == "--device") config.device = value;
            else if (flag == "--spp") spp = std::max(2, std::stoi(value));
            else if (flag == "--noise-threshold") threshold = std::stod(value);
            else if (flag == "--repeats") repeats = std::max(1, std::stoi(value));
            else throw std::runtime_error("unknown option " + flag);
        }

        Renderer renderer(scene, config);
        if (!renderer.decides_on_device())
            throw std::runtime_error("this renderer decides on the host only (several devices, no fp64, or ORB_DEVICE_DECISIONS=0)");
        renderer.render_pass(spp);
        std::vector<std::uint32_t> every(static_cast<std::size_t>(renderer.pixel_count()));
        std::iota(every.begin(), every.end(), std::uint32_t{0});
        const auto all_active = [&] { renderer.set_active_pixels(every); };

        orb::Film film;
        double host_estimate = 0;
        std::vector<std::uint32_t> host_kept;
        // As AdaptiveSampler decides without the device.
        const Timing host = time_repeats(repeats, all_active, [&] {
            renderer.read_film(film);
            const std::vector<double> errors = orb::film::pixel_relmse(film);
            host_estimate = orb::film::frame_relmse(errors);
            host_kept = orb::film::pixels_still_sampling(errors, film.width, film.height, threshold, every);
            renderer.set_active_pixels(host_kept);
        });
        const Timing host_estimate_only = time_repeats(repeats, [] {}, [&] {
            renderer.read_film(film);
            host_estimate = orb::film::frame_relmse(orb::film::pixel_relmse(film));
        });
        Renderer::Decision decision;
        const Timing device = time_repeats(repeats, all_active, [&] { decision = *renderer.decide_on_device(threshold); });
        const bool same_list = renderer.active_pixels() == host_kept;
        const Timing device_estimate_only =
            time_repeats(repeats, [] {}, [&] { decision = *renderer.decide_on_device(std::nullopt); });

        std::cout << "device=" << renderer.device().name << " size=" << config.width << "x" << config.height
                  << " spp=" << spp << " noise_threshold=" << threshold << " kept=" << host_kept.size() << " of "
                  << every.size() << "\n"
                  << "host_decision_ms=" << host << "\n"
                  << "device_decision_ms=" << device << "\n"
                  << "host_estimate_only_ms=" << host_estimate_only << "\n"
                  << "device_estimate_only_ms=" << device_estimate_only << "\n"
                  << "same_decision=" << (same_list && decision.estimated_relmse == host_estimate ? "yes" : "NO")
                  << "\n";
        return same_list && decision.estimated_relmse == host_estimate ? 0 : 1;
    } catch (const std::exception& error) {
        std::cerr << "orb-adaptive-decision-benchmark: error: " << error.what() << "\n";
        return 1;
    }
}
