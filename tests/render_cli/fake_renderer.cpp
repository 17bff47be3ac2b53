#include "fake_renderer.h"

#include <chrono>
#include <thread>

#include "orb/render/renderer.h"

namespace orb::render {

namespace fake {
Control& control() {
    static Control c;
    return c;
}
}  // namespace fake

struct Renderer::Impl {
    RenderConfig config;
    DeviceInfo device;
    std::uint64_t spp = 0;
};

Renderer::Renderer(const Scene&, const RenderConfig& config) : impl_(std::make_unique<Impl>()) {
    impl_->config = config;
    impl_->device.name = "fake";
}
Renderer::~Renderer() = default;
const DeviceInfo& Renderer::device() const { return impl_->device; }
const RenderConfig& Renderer::config() const { return impl_->config; }
int Renderer::suggested_samples_per_pass() const { return fake::control().suggested; }

void Renderer::render_pass(int samples) {
    auto& c = fake::control();
    if (c.during_pass) c.during_pass(static_cast<int>(c.passes.size()));
    c.passes.push_back(samples);
    std::this_thread::sleep_for(std::chrono::duration<double>(c.seconds_per_sample * samples));
    impl_->spp += static_cast<std::uint64_t>(samples);
}

std::uint64_t Renderer::samples_per_pixel() const { return impl_->spp; }
Film Renderer::read_film() const { return {}; }
void Renderer::load_film(const Film& film) { impl_->spp = film.samples_per_pixel; }
std::uint64_t Renderer::device_memory_bytes() const { return 0; }

}  // namespace orb::render
