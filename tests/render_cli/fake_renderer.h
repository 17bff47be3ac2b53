// A stand-in for render::Renderer, linked instead of librender into the
// progressive-loop test only: it "renders" by sleeping a set time per sample
// and records the pass sizes it was asked for.
#pragma once

#include <atomic>
#include <functional>
#include <vector>

namespace orb::render::fake {

struct Control {
    double seconds_per_sample = 0.0;  // sleep per sample per pass
    int suggested = 4;                // suggested_samples_per_pass()
    std::vector<int> passes;          // sizes of the passes rendered
    std::function<void(int pass_index)> during_pass;  // runs inside render_pass (e.g. raise a stop flag)
};

Control& control();  // reset by each test

}  // namespace orb::render::fake
