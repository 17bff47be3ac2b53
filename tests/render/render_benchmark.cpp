// orb-render-benchmark: samples per second of the path tracer on one scene,
// for docs/performance.md (orb-render --benchmark offers the same through
// the CLI). Usage:
//   orb-render-benchmark SCENE.scn [--width W] [--height H] [--seconds S]
//                        [--device SEL] [--max-depth D] [--mode global|direct]
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "orb/render/renderer.h"
#include "orb/scene/scn.h"

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::cerr << "usage: orb-render-benchmark SCENE.scn [--width W] [--height H] [--seconds S] "
                     "[--device SEL] [--max-depth D] [--mode global|direct]\n";
        return 2;
    }
    try {
        std::ifstream in(argv[1], std::ios::binary);
        if (!in) throw std::runtime_error(std::string("cannot read ") + argv[1]);
        std::ostringstream text;
        text << in.rdbuf();
        const orb::Scene scene = orb::parse_scn(text.str(), argv[1]);

        orb::render::RenderConfig config;
        double seconds = 5.0;
        for (int i = 2; i + 1 < argc; i += 2) {
            const std::string flag = argv[i], value = argv[i + 1];
            if (flag == "--width") config.width = std::stoi(value);
            else if (flag == "--height") config.height = std::stoi(value);
            else if (flag == "--seconds") seconds = std::stod(value);
            else if (flag == "--device") config.device = value;
            else if (flag == "--max-depth") config.max_depth = std::stoi(value);
            else if (flag == "--mode") config.mode = value == "direct" ? orb::render::IntegratorMode::Direct
                                                                       : orb::render::IntegratorMode::Global;
            else throw std::runtime_error("unknown option " + flag);
        }
        orb::render::Renderer renderer(scene, config);
        std::cout << "device=" << renderer.device().name << " (" << renderer.device().platform << ")\n";
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
