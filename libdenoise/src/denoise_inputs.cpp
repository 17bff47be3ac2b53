#include "denoise_inputs.h"

#include <algorithm>
#include <cmath>

#include "orb/scene/error.h"

namespace orb::denoise::detail {
namespace {

std::string format(const Names& names) { return std::string(names[0]) + ", " + names[1] + ", " + names[2]; }

bool has_all(const std::function<bool(const char*)>& has, const Names& names) {
    return std::all_of(names.begin(), names.end(), has);
}

}  // namespace

Names names_of(film::Channel channel) {
    const film::ChannelInfo& info = film::info(channel);
    return {info.exr_names[0], info.exr_names[1], info.exr_names[2]};
}

Names denoised_names() {
    const film::PostLayerInfo& info = film::info(film::PostLayer::Denoised);
    return {info.exr_names[0], info.exr_names[1], info.exr_names[2]};
}

void require_layers(const std::function<bool(const char*)>& has, const std::string& source) {
    const Names beauty = names_of(film::Channel::radiance);
    if (!has_all(has, beauty)) throw InputError(source + ": no beauty layer (" + format(beauty) + ") to denoise");
    const Names albedo = names_of(film::Channel::albedo);
    const Names normal = names_of(film::Channel::normal);
    std::string missing;
    if (!has_all(has, albedo)) missing = "no albedo layer (" + format(albedo) + ")";
    if (!has_all(has, normal))
        missing += (missing.empty() ? "no " : " and no ") + std::string("normal layer (") + format(normal) + ")";
    if (!missing.empty())
        throw InputError(source + ": " + missing +
                         "; the denoiser needs both to keep edges and textures: render with --passes "
                         "beauty,albedo,normal (orb-render --denoise adds them)");
}

void require_finite(float value, std::size_t i, int width, const std::string& channel, const char* layer,
                    const std::string& source) {
    if (std::isfinite(value)) return;
    const auto w = static_cast<std::size_t>(width);
    throw InputError(source + ": " + layer + " pixel (" + std::to_string(i % w) + ", " + std::to_string(i / w) +
                     ") channel " + channel + " is " + std::to_string(value) + "; the denoiser needs finite values");
}

}  // namespace orb::denoise::detail
