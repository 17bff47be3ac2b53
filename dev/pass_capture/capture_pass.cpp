// orb-capture-pass: renders a scene as `orb-render --benchmark` does (passes
// sized by the pass tuner) and writes one of its passes to a folder for
// orb-cuda-replay (pass_capture.h; docs/design/register-caps.md and
// speculative-traversal.md say what it measured).
//
//   orb-capture-pass SCENE --out DIR [--skip N] [--seconds S] [--device SEL]
//                    [--width W] [--height H] [--max-depth D]
//
// --skip N lets N passes go by first (default 8: the tuner's first passes are
// short). The development knobs (ORB_CL_OPTIONS, ORB_LOCAL_SIZE, ...) apply
// as in orb-render. Exit status 1 when no pass was captured within S seconds
// (default 5) or the folder could not be written, 2 for a bad command line.
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "benchmark_support.h"
#include "orb/render/renderer.h"
#include "pass_capture.h"

namespace {

constexpr const char* kUsage =
    "usage: orb-capture-pass SCENE --out DIR [--skip N] [--seconds S] [--device SEL] [--width W] [--height H] "
    "[--max-depth D]\n";

int parse_int(const std::string& flag, const std::string& value, int lowest)
{
    std::size_t used = 0;
    int number = 0;
    try {
        number = std::stoi(value, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != value.size() || value.empty() || number < lowest)
        throw std::invalid_argument(flag + " " + value + ": expected an integer >= " + std::to_string(lowest));
    return number;
}

}  // namespace

int main(int argc, char** argv)
{
    using namespace orb;
    if (argc < 2 || argc % 2 != 0) {
        std::cerr << kUsage;
        return 2;
    }
    render::RenderConfig config;
    std::string out;
    int skip = 8;
    double seconds = 5.0;
    try {
        for (int i = 2; i + 1 < argc; i += 2) {
            const std::string flag = argv[i], value = argv[i + 1];
            if (flag == "--out") out = value;
            else if (flag == "--skip") skip = parse_int(flag, value, 0);
            else if (flag == "--seconds") seconds = parse_int(flag, value, 1);
            else if (flag == "--device") config.device = value;
            else if (flag == "--width") config.width = parse_int(flag, value, 1);
            else if (flag == "--height") config.height = parse_int(flag, value, 1);
            else if (flag == "--max-depth") config.max_depth = parse_int(flag, value, 0);
            else throw std::invalid_argument("unknown option " + flag);
        }
        if (out.empty()) throw std::invalid_argument("--out DIR is required");
        if (std::filesystem::exists(out) && !std::filesystem::is_empty(out))
            throw std::invalid_argument("--out " + out + ": not empty; a capture is never written over another");
    } catch (const std::invalid_argument& error) {
        std::cerr << "orb-capture-pass: error: " << error.what() << "\n" << kUsage;
        return 2;
    }
    config.development = bench::development_knobs_or_exit("orb-capture-pass");
    const auto capture = std::make_shared<render::PassCapture>(out, skip);
    config.development.pass_observer = capture;
    try {
        const Scene scene = bench::import_scene_file(argv[1]);
        render::Renderer renderer(scene, config);
        std::cout << "device=" << renderer.device().name << " (" << renderer.device().platform << ")\n";
        const render::BenchmarkResult result = render::run_benchmark(renderer, seconds);
        if (!capture->taken())
            throw std::runtime_error("no pass captured: " + std::to_string(result.passes) +
                                     " timed passes in " + std::to_string(seconds) +
                                     " s, fewer than --skip " + std::to_string(skip) +
                                     " and one more; lower --skip or raise --seconds");
    } catch (const std::exception& error) {
        std::cerr << "orb-capture-pass: error: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
