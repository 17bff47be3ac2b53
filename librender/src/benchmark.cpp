#include <algorithm>
#include <chrono>

#include "orb/render/renderer.h"

namespace orb::render {

BenchmarkResult run_benchmark(PassRenderer& renderer, double seconds)
{
    using clock = std::chrono::steady_clock;
    const auto elapsed_since = [](clock::time_point t) { return std::chrono::duration<double>(clock::now() - t).count(); };

    // Warm-up: lets the driver finish lazy compilation and the pass tuner
    // settle on its pass size, for a few passes or a fifth of the budget.
    const auto warm_start = clock::now();
    for (int pass = 0; pass < 3 || elapsed_since(warm_start) < std::min(1.0, 0.2 * seconds); ++pass)
        renderer.render_pass(renderer.suggested_samples_per_pass());

    BenchmarkResult result;
    std::uint64_t spp = 0;
    const auto start = clock::now();
    do {
        const int samples = renderer.suggested_samples_per_pass();
        renderer.render_pass(samples);
        spp += static_cast<std::uint64_t>(samples);
        ++result.passes;
    } while (elapsed_since(start) < seconds);
    result.seconds = elapsed_since(start);
    result.samples = spp * renderer.pixel_count();
    result.samples_per_second = static_cast<double>(result.samples) / result.seconds;
    return result;
}

}  // namespace orb::render
