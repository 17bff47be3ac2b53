#include "environment_layout.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "environment_distribution.h"

namespace orb::render {

EnvironmentLayout layout_environment(const Environment& environment) {
    EnvironmentLayout layout;
    int width = 1, height = 1;
    std::vector<float> radiance;  // RGB per texel, the intensity applied
    switch (environment.kind) {
        case EnvironmentKind::None: return layout;
        case EnvironmentKind::Color:
            radiance = {static_cast<float>(environment.color[0]), static_cast<float>(environment.color[1]),
                        static_cast<float>(environment.color[2])};
            break;
        case EnvironmentKind::Map: {
            if (!environment.image)
                throw std::invalid_argument("the environment map \"" + environment.map +
                                            "\" has not been loaded (orb::exr::load_environment_map)");
            const EnvironmentImage& image = *environment.image;
            width = image.width;
            height = image.height;
            if (width < 1 || height < 1 ||
                image.rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3)
                throw std::invalid_argument("the environment map \"" + environment.map + "\" does not fill its size");
            radiance.resize(image.rgb.size());
            for (std::size_t i = 0; i < radiance.size(); ++i)
                radiance[i] = static_cast<float>(environment.intensity * image.rgb[i]);
            break;
        }
    }

    const std::size_t texels = radiance.size() / 3;
    std::vector<double> weights(texels);
    for (std::size_t i = 0; i < texels; ++i)
        weights[i] = (double(radiance[3 * i]) + double(radiance[3 * i + 1]) + double(radiance[3 * i + 2])) / 3.0;
    const EnvironmentDistribution distribution = build_environment_distribution(weights, width, height);
    if (!(distribution.total_weight > 0)) return layout;  // black: no light, nothing to see

    layout.emits = true;
    layout.texels.resize(texels);
    for (std::size_t i = 0; i < texels; ++i)
        layout.texels[i].radiance_pdf = {radiance[3 * i], radiance[3 * i + 1], radiance[3 * i + 2],
                                         static_cast<float>(distribution.pdf[i])};
    layout.cdf.reserve(distribution.cdf.size());
    for (float upper : distribution.cdf) layout.cdf.push_back({upper});

    const double turn = environment.kind == EnvironmentKind::Map ? std::fmod(environment.rotation_deg, 360.0) * std::numbers::pi / 180.0 : 0.0;
    layout.params.rotation = {static_cast<float>(std::cos(turn)), static_cast<float>(std::sin(turn)), 0.0f, 0.0f};
    layout.params.width = width;
    layout.params.height = height;
    return layout;
}

}  // namespace orb::render
