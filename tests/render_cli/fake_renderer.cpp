#include "fake_renderer.h"

#include <chrono>
#include <thread>

namespace orb::render::fake {

Control& control() {
    static Control c;
    return c;
}

void FakeRenderer::render_pass(int samples) {
    auto& c = control();
    if (c.during_pass) c.during_pass(static_cast<int>(c.passes.size()));
    c.passes.push_back(samples);
    std::this_thread::sleep_for(std::chrono::duration<double>(c.seconds_per_sample * samples));
    spp_ += static_cast<std::uint64_t>(samples);
}

}  // namespace orb::render::fake
