#include "orb/render/film.h"

#include <limits>
#include <stdexcept>

namespace orb::render {

void Film::resize(int w, int h)
{
    if (w < 0 || h < 0) throw std::invalid_argument("film size must not be negative");
    width = w;
    height = h;
    samples_per_pixel = 0;
    const size_t n = pixel_count();
    for (std::vector<float>* set : {&radiance, &radiance_sq, &direct, &indirect, &emission, &albedo, &normal})
        set->assign(n * 3, 0.0f);
    alpha.assign(n, 0.0f);
    depth.assign(n, std::numeric_limits<float>::infinity());
    object_id.assign(n, -1.0f);
}

void Film::accumulate(const Film& other)
{
    if (other.width != width || other.height != height)
        throw std::invalid_argument("cannot add a " + std::to_string(other.width) + "x" + std::to_string(other.height) +
                                    " film to a " + std::to_string(width) + "x" + std::to_string(height) + " one");
    const bool this_empty = samples_per_pixel == 0;
    const auto add = [](std::vector<float>& into, const std::vector<float>& from) {
        if (into.size() != from.size()) throw std::invalid_argument("film channel sizes differ");
        for (size_t i = 0; i < into.size(); ++i) into[i] += from[i];
    };
    add(radiance, other.radiance);
    add(radiance_sq, other.radiance_sq);
    add(direct, other.direct);
    add(indirect, other.indirect);
    add(emission, other.emission);
    add(albedo, other.albedo);
    add(normal, other.normal);
    add(alpha, other.alpha);
    if (this_empty) {
        depth = other.depth;
        object_id = other.object_id;
    }
    samples_per_pixel += other.samples_per_pixel;
}

}  // namespace orb::render
