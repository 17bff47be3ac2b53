// A stand-in for the OpenCL renderer, for the progressive-loop test only: it
// "renders" by sleeping a set time per sample and records the pass sizes it
// was asked for.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "orb/film/film.h"
#include "orb/render/pass_renderer.h"

namespace orb::render::fake {

struct Control {
    double seconds_per_sample = 0.0;  // sleep per sample per pass
    int suggested = 4;                // suggested_samples_per_pass()
    std::vector<int> passes;          // sizes of the passes rendered
    std::function<void(int pass_index)> during_pass;  // runs inside render_pass (e.g. raise a stop flag)
};

Control& control();  // reset by each test

class FakeRenderer final : public PassRenderer {
public:
    explicit FakeRenderer(std::uint64_t pixels) : pixels_(pixels) {}

    int suggested_samples_per_pass() const override { return control().suggested; }
    void render_pass(int samples) override;
    std::uint64_t samples_per_pixel() const override { return spp_; }
    std::uint64_t pixel_count() const override { return pixels_; }

    void load_film(const Film& film) { spp_ = film.samples_per_pixel; }

private:
    std::uint64_t pixels_;
    std::uint64_t spp_ = 0;
};

}  // namespace orb::render::fake
