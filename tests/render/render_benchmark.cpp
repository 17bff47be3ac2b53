// orb-render-benchmark: samples per second of the path tracer on one scene,
// for the records in docs/design (orb-render --benchmark offers the same
// through the CLI). Usage:
//   orb-render-benchmark SCENE.scn [--width W] [--height H] [--seconds S]
//                        [--device SEL] [--max-depth D] [--mode global|direct]
//                        [--cpu-spp N [--pass-spp K]]  (N samples in passes of K, reports samples
//                                                       per CPU-second instead)
//                        [--channels beauty|all]  (the film channels computed; default all)
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "benchmark_support.h"
#include "orb/render/renderer.h"
#include "orb/import/scn.h"

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::cerr << "usage: orb-render-benchmark SCENE.scn [--width W] [--height H] [--seconds S] "
                     "[--device SEL] [--max-depth D] [--mode global|direct] [--cpu-spp N]\n";
        return 2;
    }
    try {
        std::ifstream in(argv[1], std::ios::binary);
        if (!in) throw std::runtime_error(std::string("cannot read ") + argv[1]);
        std::ostringstream text;
        text << in.rdbuf();
        const orb::Scene scene = orb::parse_scn(text.str(), argv[1]);

        orb::render::RenderConfig config;
        config.development = orb::bench::development_knobs_or_exit("orb-render-benchmark");
        double seconds = 5.0;
        int cpu_spp = 0, pass_spp = 1;
        for (int i = 2; i + 1 < argc; i += 2) {
            const std::string flag = argv[i], value = argv[i + 1];
            if (flag == "--width") config.width = std::stoi(value);
            else if (flag == "--height") config.height = std::stoi(value);
            else if (flag == "--seconds") seconds = std::stod(value);
            else if (flag == "--device") config.device = value;
            else if (flag == "--cpu-spp") cpu_spp = std::stoi(value);
            else if (flag == "--pass-spp") pass_spp = std::max(1, std::stoi(value));
            else if (flag == "--channels")  // beauty: only what orb-render's default output computes; all: every channel
                config.film_channels = value == "beauty" ? orb::film::channels_for(std::array{orb::film::Layer::Beauty})
                                                         : orb::film::kAllChannels;
            else if (flag == "--max-depth") config.max_depth = std::stoi(value);
            else if (flag == "--mode") config.mode = value == "direct" ? orb::render::IntegratorMode::Direct
                                                                       : orb::render::IntegratorMode::Global;
            else throw std::runtime_error("unknown option " + flag);
        }
        orb::render::Renderer renderer(scene, config);
        std::cout << "device=" << renderer.device().name << " (" << renderer.device().platform << ")\n";
        const auto cpu_seconds = [] {
            rusage usage{};
            getrusage(RUSAGE_SELF, &usage);
            return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
        };
        if (cpu_spp > 0) {
            // On a shared machine, samples per CPU-second compares kernel
            // variants more steadily than wall time: one warm-up pass, then
            // passes of `pass_spp` samples up to `cpu_spp` samples.
            renderer.render_pass(1);
            const double cpu_before = cpu_seconds();
            for (int i = 0; i < cpu_spp; i += pass_spp) renderer.render_pass(pass_spp);
            const double cpu_used = cpu_seconds() - cpu_before;
            std::cout << "samples_per_cpu_second="
                      << static_cast<double>(cpu_spp) * config.width * config.height / cpu_used << "\n";
            return 0;
        }
        const orb::render::BenchmarkResult result = orb::render::run_benchmark(renderer, seconds);
        std::cout << "size=" << config.width << "x" << config.height << " max_depth=" << config.max_depth
                  << " passes=" << result.passes << " samples=" << result.samples << " seconds=" << result.seconds
                  << " spp_per_pass=" << renderer.suggested_samples_per_pass() << "\n";
        std::cout << "samples_per_second=" << result.samples_per_second << "\n";
    } catch (const std::exception& error) {
        std::cerr << "orb-render-benchmark: error: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
