#include "orb/denoise/denoise_film.h"

#include <array>
#include <chrono>
#include <span>

#include "denoise_inputs.h"
#include "orb/denoise/denoise_exr.h"
#include "orb/film/parallel_blocks.h"

namespace orb::denoise {
namespace {

// The layer's three channels interleaved into `out`, as a reader of the
// file gets them back, each value finite.
void interleave(const exr::StoredImage& image, film::Channel layer_channel, const std::string& source,
                const char* layer, float* out) {
    const detail::Names names = detail::names_of(layer_channel);
    const std::array<const exr::StoredImage::Channel*, 3> channels{image.find(names[0]), image.find(names[1]),
                                                                   image.find(names[2])};
    const std::size_t pixels = static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(image.height());
    detail::interleave_into(out, pixels, image.width(), names, layer, source, [&](int c, std::size_t i) {
        return exr::StoredImage::value(*channels[static_cast<std::size_t>(c)], i);
    });
}

}  // namespace

exr::PostLayerPlanes denoised_post_layer(Denoiser& denoiser, const std::string& source,
                                         std::shared_ptr<DenoiseTimes> times) {
    exr::PostLayerPlanes layer;
    layer.layer = film::PostLayer::Denoised;
    layer.attributes = {{kDenoisedAttribute, denoiser.description()}};
    layer.compute = [&denoiser, source, times](const exr::StoredImage& image, std::span<const std::span<float>> out) {
        const auto start = std::chrono::steady_clock::now();
        detail::require_layers([&](const char* name) { return image.find(name) != nullptr; }, source);
        Denoiser::Job job = denoiser.begin(image.width(), image.height());
        interleave(image, film::Channel::radiance, source, "beauty", job.color());
        job.send(Denoiser::Job::Input::Color);
        interleave(image, film::Channel::albedo, source, "albedo", job.albedo());
        job.send(Denoiser::Job::Input::Albedo);
        interleave(image, film::Channel::normal, source, "normal", job.normal());
        const std::span<const float> denoised = job.run();
        // Back to the encoder's planes, one per channel, on every core.
        film::for_each_block(denoised.size() / 3, [&](std::size_t, std::size_t first, std::size_t end) {
            const float* __restrict from = denoised.data();
            for (std::size_t c = 0; c < out.size(); ++c) {
                float* __restrict to = out[c].data();
                for (std::size_t i = first; i < end; ++i) to[i] = from[3 * i + c];
            }
        });
        if (times)
            *times = {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                      job.setup_seconds(), job.filter_seconds()};
    };
    return layer;
}

}  // namespace orb::denoise
