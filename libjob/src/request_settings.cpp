#include "orb/job/request_settings.h"

#include "orb/tables/render_names.h"

namespace orb::job {
namespace {

// SplitMix64's output function (Steele, Lea, Flood 2014): a bijection of
// 64-bit words that mixes every input bit into every output bit.
std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

}  // namespace

const std::vector<exr::Pass>& default_passes() {
    static const std::vector<exr::Pass> passes{exr::Pass::Beauty};
    return passes;
}

double frame_time(long frame, double fps) { return static_cast<double>(frame) / fps; }

std::uint64_t frame_seed(std::uint64_t seed, long frame) {
    return mix64(seed ^ mix64(static_cast<std::uint64_t>(frame) + 1));
}

std::uint64_t RequestSettings::seed_of(std::optional<long> frame) const {
    return frame && !same_seed ? frame_seed(seed, *frame) : seed;
}

exr::RenderRequest RequestSettings::request(std::optional<long> frame, double scene_time) const {
    exr::RenderRequest r;
    r.scene_time = frame ? frame_time(*frame, fps) : scene_time;
    r.width = width;
    r.height = height;
    r.mode = mode;
    r.sampler = sampler;
    r.max_depth = max_depth;
    r.seed = seed_of(frame);
    r.passes = passes;
    r.half = half;
    r.slice = slice;
    r.first_sample = first_sample;
    r.spp = spp;
    return r;
}

RequestSettings resolve_settings(const GivenSettings& given, const RenderSettings* scene) {
    RequestSettings s;
    const auto from_scene = [&](const std::optional<int>& value, int RenderSettings::*field) -> std::optional<int> {
        if (value) return value;
        if (scene) return (*scene).*field;
        return std::nullopt;
    };
    s.width = from_scene(given.width, &RenderSettings::width);
    s.height = from_scene(given.height, &RenderSettings::height);
    s.max_depth = from_scene(given.max_depth, &RenderSettings::max_depth);
    if (given.spp) s.spp = *given.spp;
    else if (scene) s.spp = static_cast<std::uint64_t>(scene->spp);
    if (given.sample_range) {
        s.slice = true;
        s.first_sample = given.sample_range->first;
        s.spp = given.sample_range->count;
    }
    s.seed = given.seed.value_or(0);
    if (given.mode) s.mode = *given.mode;  // else the table's default (request_settings.h)
    if (given.sampler) s.sampler = *given.sampler;
    if (given.passes) s.passes = *given.passes;
    s.half = given.half;
    s.fps = given.fps.value_or(kDefaultFps);
    s.same_seed = given.same_seed;
    return s;
}

}  // namespace orb::job
