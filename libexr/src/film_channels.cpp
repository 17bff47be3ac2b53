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

// The samples each pixel's sums are over: the film's samples_per_pixel, or,
// in a file with the samples layer (adaptive sampling), each pixel's own
// count from the sample_count channel.
struct Counts {
    double uniform = 0;
    const float* per_pixel = nullptr;

    double at(std::size_t pixel) const { return per_pixel ? static_cast<double>(per_pixel[pixel]) : uniform; }
};

Counts film_counts(const Film& film, const std::vector<Pass>& passes) {
    Counts counts{static_cast<double>(film.samples_per_pixel), nullptr};
    if (contains(passes, film::Layer::Samples)) {
        if (film.sample_count.size() != film.pixel_count())
            throw std::invalid_argument("the samples layer needs the film's sample_count channel");
        counts.per_pixel = film.sample_count.data();
    }
    return counts;
}

// Each of these fills pixels [first, end) of its output planes.

// Means are computed in double and rounded once, so mean * n gives the sum
// back within a float rounding or two. A multiplication by 1/n (within a
// double's rounding of the quotient, so the same float nearly always) and
// every component in one sweep over the sums: this is most of what writing a
// frame costs besides compressing it.
void mean_channel(const Sums& sums, int components, const Counts& counts, std::span<const Plane> out,
                  std::size_t first, std::size_t end) {
    if (counts.per_pixel) {
        for (std::size_t i = first; i < end; ++i) {
            const double n = counts.at(i);
            for (int c = 0; c < components; ++c)
                out[c].values[i] =
                    n > 0 ? static_cast<float>(static_cast<double>(sums[i * components + c]) / n) : 0.0f;
        }
        return;
    }
    const double inverse = 1.0 / counts.uniform;
    if (components == 1) {
        float* to = out[0].values.data();
        for (std::size_t i = first; i < end; ++i) to[i] = static_cast<float>(static_cast<double>(sums[i]) * inverse);
        return;
    }
    float* to[3] = {out[0].values.data(), out[1].values.data(), out[2].values.data()};
    for (std::size_t i = first; i < end; ++i)
        for (int c = 0; c < 3; ++c) to[c][i] = static_cast<float>(static_cast<double>(sums[i * 3 + c]) * inverse);
}

// Variance of the pixel mean: the unbiased sample variance divided by n,
// (sum_sq/n - mean^2) * n/(n-1) / n. Zero with fewer than two samples,
// where it is unknown (and where sum_sq = mean^2 recovers exactly).
void variance_channel(const Sums& sums, const Sums& sums_sq, int components, int component, const Counts& counts,
                      std::span<float> out, std::size_t first, std::size_t end) {
    for (std::size_t i = first; i < end; ++i) {
        const double nd = counts.at(i);
        if (nd < 2) {
            out[i] = 0.0f;
            continue;
        }
        const double mean = static_cast<double>(sums[i * components + component]) / nd;
        const double mean_sq = static_cast<double>(sums_sq[i * components + component]) / nd;
        out[i] = static_cast<float>(std::max(0.0, mean_sq - mean * mean) / (nd - 1.0));
    }
}

// The mean normalised (0 where it is 0), then its length: planes
// out[0 .. components-1] and out[components].
void unit_vector_planes(const Sums& sums, int components, const Counts& counts, std::span<const Plane> out,
                        std::size_t first, std::size_t end) {
    for (std::size_t i = first; i < end; ++i) {
        const double n = counts.at(i) > 0 ? counts.at(i) : 1.0;  // no samples: the sums are 0
        double mean[3] = {0, 0, 0};
        double length_sq = 0;
        for (int c = 0; c < components; ++c) {
            mean[c] = sums[i * components + c] / n;
            length_sq += mean[c] * mean[c];
        }
        const double length = std::sqrt(length_sq);
        const double scale = length > 0 ? 1.0 / length : 0.0;
        for (int c = 0; c < components; ++c) out[c].values[i] = static_cast<float>(mean[c] * scale);
        out[components].values[i] = static_cast<float>(length);
    }
}

void component_values(const Sums& values, int components, int component, std::span<float> out, std::size_t first,
                      std::size_t end) {
    for (std::size_t i = first; i < end; ++i) out[i] = values[i * components + component];
}

const std::vector<float>& plane(const Planes& planes, const std::string& name) {
    auto it = planes.find(name);
    if (it == planes.end()) throw std::logic_error("channel " + name + " was not read");
    return it->second;
}

void recover_means(const Planes& planes, const ChannelInfo& channel, const Counts& counts, Sums& sums) {
    const int components = channel.components;
    for (int c = 0; c < components; ++c) {
        const auto& means = plane(planes, channel.exr_names[c]);
        for (std::size_t i = 0; i < means.size(); ++i)
            sums[i * components + c] = static_cast<float>(static_cast<double>(means[i]) * counts.at(i));
    }
}

void recover_unit_vector(const Planes& planes, const ChannelInfo& channel, const Counts& counts, Sums& sums) {
    const int components = channel.components;
    const auto& length = plane(planes, channel.exr_names[components]);
    for (int c = 0; c < components; ++c) {
        const auto& unit = plane(planes, channel.exr_names[c]);
        for (std::size_t i = 0; i < unit.size(); ++i)
            sums[i * components + c] = static_cast<float>(static_cast<double>(unit[i]) * length[i] * counts.at(i));
    }
}

// sum_sq = n ((n-1) var + mean^2), from the paired channel's stored mean.
void recover_second_moment(const Planes& planes, const ChannelInfo& channel, const Counts& counts, Sums& sums_sq) {
    const ChannelInfo& paired = film::info(channel.paired);
    const int components = channel.components;
    for (int c = 0; c < components; ++c) {
        const auto& variance = plane(planes, channel.exr_names[c]);
        const auto& mean = plane(planes, paired.exr_names[c]);
        for (std::size_t i = 0; i < variance.size(); ++i) {
            const double n = counts.at(i);
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

std::vector<Plane> plane_layout(const Film& film, const std::vector<Pass>& passes,
                                std::vector<float>& storage) {
    const std::size_t pixels = static_cast<std::size_t>(film.width) * static_cast<std::size_t>(film.height);
    if (storage.size() < plane_count(passes) * pixels) storage.resize(plane_count(passes) * pixels);
    std::vector<Plane> planes;
    for (Pass pass : passes)
        for (const ChannelInfo* channel : pass_film_channels(pass))
            for (int c = 0; c < channel->exr_name_count; ++c) {
                // Values kept as they are (and the unit vector's length) stay FLOAT under --half.
                const bool always_float = channel->stored_as == StoredAs::Value ||
                                          (channel->stored_as == StoredAs::UnitVector && c == channel->components);
                planes.push_back({channel->exr_names[c], always_float,
                                  std::span<float>(storage.data() + planes.size() * pixels, pixels)});
            }
    return planes;
}

void fill_planes(const Film& film, const std::vector<Pass>& passes, const std::vector<Plane>& planes,
                 std::size_t first, std::size_t end) {
    if (film.samples_per_pixel == 0) throw std::invalid_argument("the film holds no samples");
    const Counts n = film_counts(film, passes);
    std::size_t next = 0;  // the planes come in plane_layout's order
    for (Pass pass : passes) {
        for (const ChannelInfo* channel : pass_film_channels(pass)) {
            const Sums& sums = film.channel(channel->channel);
            const int components = channel->components;
            switch (channel->stored_as) {
                case StoredAs::Mean:
                    mean_channel(sums, components, n, std::span(planes).subspan(next, components), first, end);
                    next += static_cast<std::size_t>(components);
                    break;
                case StoredAs::UnitVector:
                    unit_vector_planes(sums, components, n, std::span(planes).subspan(next, components + 1), first, end);
                    next += static_cast<std::size_t>(components) + 1;
                    break;
                case StoredAs::VarianceOfMean:
                    for (int c = 0; c < components; ++c)
                        variance_channel(film.channel(channel->paired), sums, components, c, n, planes[next++].values,
                                         first, end);
                    break;
                case StoredAs::Value:
                    for (int c = 0; c < components; ++c) component_values(sums, components, c, planes[next++].values, first, end);
                    break;
            }
        }
    }
}

std::vector<Plane> film_to_planes(const Film& film, const std::vector<Pass>& passes,
                                  std::vector<float>& storage) {
    if (film.samples_per_pixel == 0) throw std::invalid_argument("the film holds no samples");
    std::vector<Plane> planes = plane_layout(film, passes, storage);
    fill_planes(film, passes, planes, 0, static_cast<std::size_t>(film.width) * static_cast<std::size_t>(film.height));
    return planes;
}

void planes_to_film(const Planes& planes, const std::vector<Pass>& passes, Film& film) {
    // The pixels' own counts first: every mean is over them.
    if (contains(passes, film::Layer::Samples))
        recover_values(planes, film::info(film::Channel::sample_count), film.sample_count);
    else  // every pixel holds the film's samples
        film.sample_count.assign(film.pixel_count(), static_cast<float>(film.samples_per_pixel));
    const Counts n = film_counts(film, passes);
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
