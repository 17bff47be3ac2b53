#include "orb/denoise/denoise_film.h"

#include "denoise_inputs.h"
#include "orb/denoise/denoise_exr.h"

namespace orb::denoise {
namespace {

// The three channels interleaved, as a reader of the file gets them back,
// each value finite.
std::vector<float> interleave(const exr::StoredImage& image, const detail::Names& names, const std::string& source,
                              const char* layer) {
    const std::size_t pixels = static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(image.height());
    std::vector<float> rgb(pixels * 3);
    for (std::size_t c = 0; c < 3; ++c) {
        const exr::StoredImage::Channel& channel = *image.find(names[c]);
        for (std::size_t i = 0; i < pixels; ++i) {
            const float value = exr::StoredImage::value(channel, i);
            detail::require_finite(value, i, image.width(), std::string(channel.name), layer, source);
            rgb[3 * i + c] = value;
        }
    }
    return rgb;
}

}  // namespace

exr::PostLayerPlanes denoised_post_layer(Denoiser& denoiser, const std::string& source) {
    exr::PostLayerPlanes layer;
    layer.layer = film::PostLayer::Denoised;
    layer.attributes = {{kDenoisedAttribute, denoiser.description()}};
    layer.compute = [&denoiser, source](const exr::StoredImage& image) {
        detail::require_layers([&](const char* name) { return image.find(name) != nullptr; }, source);
        const std::vector<float> color = interleave(image, detail::names_of(film::Channel::radiance), source, "beauty");
        const std::vector<float> albedo = interleave(image, detail::names_of(film::Channel::albedo), source, "albedo");
        const std::vector<float> normal = interleave(image, detail::names_of(film::Channel::normal), source, "normal");
        return denoiser.denoise({image.width(), image.height(), color.data(), albedo.data(), normal.data()});
    };
    return layer;
}

}  // namespace orb::denoise
