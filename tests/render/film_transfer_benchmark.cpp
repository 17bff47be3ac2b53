// orb-film-transfer-benchmark: milliseconds to read the film back from the
// device (Renderer::read_film into a film reused frame after frame, as
// orb-render's frame loop does) and to upload one (load_film, as a resumed
// render does), for the channels a run computes. Usage:
//   orb-film-transfer-benchmark SCENE [--width W] [--height H] [--passes beauty|all]
//                               [--repeats N] [--device SEL]
#include <algorithm>
#include <chrono>
#include <iostream>
#include <string>
#include <vector>

#include "benchmark_support.h"
#include "orb/render/renderer.h"

namespace {

struct Timing {
    double mean_ms = 0;
    double min_ms = 0;
};

template <typename Step>
Timing time_repeats(int repeats, Step step)
{
    std::vector<double> ms;
    for (int i = 0; i < repeats; ++i) {
        const auto start = std::chrono::steady_clock::now();
        step();
        ms.push_back(1000.0 * orb::bench::seconds_since(start));
    }
    double total = 0;
    for (double m : ms) total += m;
    return {total / repeats, *std::min_element(ms.begin(), ms.end())};
}

}  // namespace

int main(int argc, char** argv)
{
    using namespace orb::render;
    if (argc < 2) {
        std::cerr << "usage: orb-film-transfer-benchmark SCENE [--width W] [--height H] [--passes beauty|all] "
                     "[--repeats N] [--device SEL]\n";
        return 2;
    }
    try {
        const orb::Scene scene = orb::bench::import_scene_file(argv[1]);
        RenderConfig config;
        config.development = orb::bench::development_knobs_or_exit("orb-film-transfer-benchmark");
        config.width = 1920;
        config.height = 1080;
        int repeats = 10;
        std::string passes = "all";
        for (int i = 2; i + 1 < argc; i += 2) {
            const std::string flag = argv[i], value = argv[i + 1];
            if (flag == "--width") config.width = std::stoi(value);
            else if (flag == "--height") config.height = std::stoi(value);
            else if (flag == "--device") config.device = value;
            else if (flag == "--repeats") repeats = std::max(1, std::stoi(value));
            else if (flag == "--passes") passes = value;
            else throw std::runtime_error("unknown option " + flag);
        }
        if (passes == "beauty")
            config.film_channels = orb::film::channels_for(std::vector{orb::film::Layer::Beauty});
        else if (passes != "all")
            throw std::runtime_error("--passes takes beauty or all");

        Renderer renderer(scene, config);
        // A first pass, then one that every device takes part in (with --device all).
        renderer.render_pass(1);
        renderer.render_pass(2 * static_cast<int>(renderer.devices().size()));
        std::string devices;
        for (std::size_t d = 0; d < renderer.devices().size(); ++d)
            devices += (d ? "; " : "") + renderer.devices()[d].name + " (" +
                       std::to_string(renderer.device_sample_ranges()[d].total()) + " spp)";
        orb::Film film;
        const Timing first = time_repeats(1, [&] { renderer.read_film(film); });
        const Timing reused = time_repeats(repeats, [&] { renderer.read_film(film); });
        const Timing upload = time_repeats(repeats, [&] { renderer.load_film(film); });
        std::cout << "devices=" << devices << " size=" << config.width << "x" << config.height
                  << " passes=" << passes << " device_film_bytes=" << renderer.device_memory_bytes() << "\n"
                  << "read_film_fresh_ms=" << first.mean_ms << "\n"
                  << "read_film_reused_ms=" << reused.mean_ms << " (min " << reused.min_ms << ")\n"
                  << "load_film_ms=" << upload.mean_ms << " (min " << upload.min_ms << ")\n";
    } catch (const std::exception& error) {
        std::cerr << "orb-film-transfer-benchmark: error: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
