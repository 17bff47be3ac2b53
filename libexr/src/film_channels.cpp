#include "film_channels.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>

namespace orb::exr::detail {
namespace {

using film::ChannelInfo;
using film::StoredAs;
using Sums = std::vector<float>;
using Planes = std::map<std::string, std::vector<float>>;

// Means are computed in double and rounded once, so mean * n gives the sum
// back within a float rounding or two.
void mean_channel(const Sums& sums, int components, int component, double n, std::span<float> out) {
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<float>(static_cast<double>(sums[i * components + component]) / n);
}

// Variance of the pixel mean: the unbiased sample variance divided by n,
// (sum_sq/n - mean^2) * n/(n-1) / n. Zero with fewer than two samples,
// where it is unknown (and where sum_sq = mean^2 recovers exactly).
void variance_channel(const Sums& sums, const Sums& sums_sq, int components, int component, std::uint64_t n,
                      std::span<float> out) {
    if (n < 2) {
        std::fill(out.begin(), out.end(), 0.0f);
        return;
    }
    const double nd = static_cast<double>(n);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double mean = static_cast<double>(sums[i * components + component]) / nd;
        const double mean_sq = static_cast<double>(sums_sq[i * components + component]) / nd;
        out[i] = static_cast<float>(std::max(0.0, mean_sq - mean * mean) / (nd - 1.0));
    }
}

// The mean normalised (0 where it is 0), then its length: planes
// out[0 .. components-1] and out[components].
void unit_vector_planes(const Sums& sums, int components, double n, const std::vector<std::span<float>>& out) {
    const std::size_t pixels = sums.size() / components;
    for (std::size_t i = 0; i < pixels; ++i) {
        double mean[3] = {0, 0, 0};
        double length_sq = 0;
        for (int c = 0; c < components; ++c) {
            mean[c] = sums[i * components + c] / n;
            length_sq += mean[c] * mean[c];
        }
        const double length = std::sqrt(length_sq);
        const double scale = length > 0 ? 1.0 / length : 0.0;
        for (int c = 0; c < components; ++c) out[c][i] = static_cast<float>(mean[c] * scale);
        out[components][i] = static_cast<float>(length);
    }
}

void component_values(const Sums& values, int components, int component, std::span<float> out) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = values[i * components + component];
}

const std::vector<float>& plane(const Planes& planes, const std::string& name) {
    auto it = planes.find(name);
    if (it == planes.end()) throw std::logic_error("channel " + name + " was not read");
    return it->second;
}

void recover_means(const Planes& planes, const ChannelInfo& channel, double n, Sums& sums) {
    const int components = channel.components;
    for (int c = 0; c < components; ++c) {
        const auto& means = plane(planes, channel.exr_names[c]);
        for (std::size_t i = 0; i < means.size(); ++i)
            sums[i * components + c] = static_cast<float>(static_cast<double>(means[i]) * n);
    }
}

void recover_unit_vector(const Planes& planes, const ChannelInfo& channel, double n, Sums& sums) {
    const int components = channel.components;
    const auto& length = plane(planes, channel.exr_names[components]);
    for (int c = 0; c < components; ++c) {
        const auto& unit = plane(planes, channel.exr_names[c]);
        for (std::size_t i = 0; i < unit.size(); ++i)
            sums[i * components + c] = static_cast<float>(static_cast<double>(unit[i]) * length[i] * n);
    }
}

// sum_sq = n ((n-1) var + mean^2), from the paired channel's stored mean.
void recover_second_moment(const Planes& planes, const ChannelInfo& channel, double n, Sums& sums_sq) {
    const ChannelInfo& paired = film::info(channel.paired);
    const int components = channel.components;
    for (int c = 0; c < components; ++c) {
        const auto& variance = plane(planes, channel.exr_names[c]);
        const auto& mean = plane(planes, paired.exr_names[c]);
        for (std::size_t i = 0; i < variance.size(); ++i) {
            const double m = mean[i];
            sums_sq[i * components + c] =
                static_cast<float>(n * ((n - 1.0) * static_cast<double>(variance[i]) + m * m));
        }
    }
}

void recover_values(const Planes& planes, const ChannelInfo& channel, Sums& values) {
    const int components = channel.components;
    for (int c = 0; c < components; ++c) {
        const auto& stored = plane(planes, channel.exr_names[c]);
        for (std::size_t i = 0; i < stored.size(); ++i) values[i * components + c] = stored[i];
    }
}

}  // namespace

std::size_t plane_count(const std::vector<Pass>& passes) {
    std::size_t count = 0;
    for (Pass pass : passes)
        for (const ChannelInfo* channel : pass_film_channels(pass)) count += static_cast<std::size_t>(channel->exr_name_count);
    return count;
}

std::vector<Plane> film_to_planes(const render::Film& film, const std::vector<Pass>& passes,
                                  std::vector<float>& storage) {
    if (film.samples_per_pixel == 0) throw std::invalid_argument("the film holds no samples");
    const double n = static_cast<double>(film.samples_per_pixel);
    const std::size_t pixels = static_cast<std::size_t>(film.width) * static_cast<std::size_t>(film.height);
    if (storage.size() < plane_count(passes) * pixels) storage.resize(plane_count(passes) * pixels);
    std::vector<Plane> planes;
    const auto next_plane = [&](const char* name, bool always_float) {
        const std::span<float> values(storage.data() + planes.size() * pixels, pixels);
        planes.push_back({name, always_float, values});
        return values;
    };
    for (Pass pass : passes) {
        for (const ChannelInfo* channel : pass_film_channels(pass)) {
            const Sums& sums = film.channel(channel->channel);
            const int components = channel->components;
            switch (channel->stored_as) {
                case StoredAs::Mean:
                    for (int c = 0; c < components; ++c)
                        mean_channel(sums, components, c, n, next_plane(channel->exr_names[c], false));
                    break;
                case StoredAs::UnitVector: {
                    std::vector<std::span<float>> out;
                    for (int c = 0; c <= components; ++c)
                        out.push_back(next_plane(channel->exr_names[c], c == components));
                    unit_vector_planes(sums, components, n, out);
                    break;
                }
                case StoredAs::VarianceOfMean:
                    for (int c = 0; c < components; ++c)
                        variance_channel(film.channel(channel->paired), sums, components, c, film.samples_per_pixel,
                                         next_plane(channel->exr_names[c], false));
                    break;
                case StoredAs::Value:
                    for (int c = 0; c < components; ++c)
                        component_values(sums, components, c, next_plane(channel->exr_names[c], true));
                    break;
            }
        }
    }
    return planes;
}

void planes_to_film(const Planes& planes, const std::vector<Pass>& passes, render::Film& film) {
    const double n = static_cast<double>(film.samples_per_pixel);
    for (Pass pass : passes) {
        for (const ChannelInfo* channel : pass_film_channels(pass)) {
            Sums& sums = film.channel(channel->channel);
            switch (channel->stored_as) {
                case StoredAs::Mean: recover_means(planes, *channel, n, sums); break;
                case StoredAs::UnitVector: recover_unit_vector(planes, *channel, n, sums); break;
                case StoredAs::VarianceOfMean:
                    // Needs the paired channel's mean, from its own pass.
                    if (contains(passes, film::info(channel->paired).layer))
                        recover_second_moment(planes, *channel, n, sums);
                    break;
                case StoredAs::Value: recover_values(planes, *channel, sums); break;
            }
        }
    }
}

}  // namespace orb::exr::detail
