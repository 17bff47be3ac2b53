#include "film_channels.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <span>
#include <stdexcept>

namespace orb::exr::detail {
namespace {

using film::ChannelInfo;
using film::StoredAs;
using film::Sum;
using Sums = std::vector<Sum>;
using Values = std::map<std::string, std::vector<float>>;

// The samples each pixel's sums are over: the film's samples_per_pixel, or,
// in a file with the samples layer (adaptive sampling), each pixel's own
// count from the sample_count channel.
struct Counts {
    double uniform = 0;
    const Sum* per_pixel = nullptr;

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

// Means are computed in double from the exact sums and rounded once. A
// multiplication by 1/n (within a double's rounding of the quotient) and
// every component in one sweep over the sums: this is most of what writing
// a frame costs besides compressing it.
void mean_channel(const ChannelInfo& channel, const Sums& sums, const Counts& counts, std::span<const Plane> out,
                  std::size_t first, std::size_t end) {
    const int components = channel.components;
    const double unit = film::unit_value(channel.units);
    if (counts.per_pixel) {
        for (std::size_t i = first; i < end; ++i) {
            const double n = counts.at(i);
            for (int c = 0; c < components; ++c)
                out[c].values[i] =
                    n > 0 ? static_cast<float>(static_cast<double>(sums[i * components + c]) * unit / n) : 0.0f;
        }
        return;
    }
    const double inverse = unit / counts.uniform;
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
// where it is unknown.
void variance_channel(const ChannelInfo& channel, const Sums& sums, const Sums& sums_sq, int component,
                      const Counts& counts, std::span<float> out, std::size_t first, std::size_t end) {
    const int components = channel.components;
    for (std::size_t i = first; i < end; ++i) {
        const double nd = counts.at(i);
        if (nd < 2) {
            out[i] = 0.0f;
            continue;
        }
        const double mean = film::sum_value(film::Units::Fixed, sums[i * components + component]) / nd;
        const double mean_sq = film::sum_value(film::Units::Fixed, sums_sq[i * components + component]) / nd;
        out[i] = static_cast<float>(std::max(0.0, mean_sq - mean * mean) / (nd - 1.0));
    }
}

// The mean normalised (0 where it is 0), then its length: planes
// out[0 .. components-1] and out[components].
void unit_vector_planes(const ChannelInfo& channel, const Sums& sums, const Counts& counts,
                        std::span<const Plane> out, std::size_t first, std::size_t end) {
    const int components = channel.components;
    for (std::size_t i = first; i < end; ++i) {
        const double n = counts.at(i) > 0 ? counts.at(i) : 1.0;  // no samples: the sums are 0
        double mean[3] = {0, 0, 0};
        double length_sq = 0;
        for (int c = 0; c < components; ++c) {
            mean[c] = film::sum_value(channel.units, sums[i * components + c]) / n;
            length_sq += mean[c] * mean[c];
        }
        const double length = std::sqrt(length_sq);
        const double scale = length > 0 ? 1.0 / length : 0.0;
        for (int c = 0; c < components; ++c) out[c].values[i] = static_cast<float>(mean[c] * scale);
        out[components].values[i] = static_cast<float>(length);
    }
}

// A Value channel as it is: a centre-ray value, or a count (as a float).
void component_values(const Film& film, const ChannelInfo& channel, int component, std::span<float> out,
                      std::size_t first, std::size_t end) {
    const auto components = static_cast<std::size_t>(channel.components);
    const auto c = static_cast<std::size_t>(component);
    if (channel.accumulation == film::Accumulation::Sum) {
        const Sums& sums = film.sums(channel.channel);
        for (std::size_t i = first; i < end; ++i) out[i] = static_cast<float>(sums[i * components + c]);
        return;
    }
    const std::vector<float>& values = film.values(channel.channel);
    for (std::size_t i = first; i < end; ++i) out[i] = values[i * components + c];
}

// The exact sums of a channel: each component's low then high 32 bits, their
// bits held in the float planes (stored as UINT).
void exact_planes(const ChannelInfo& channel, const Sums& sums, std::span<const Plane> out, std::size_t first,
                  std::size_t end) {
    const auto components = static_cast<std::size_t>(channel.components);
    for (std::size_t c = 0; c < components; ++c) {
        float* low = out[2 * c].values.data();
        float* high = out[2 * c + 1].values.data();
        for (std::size_t i = first; i < end; ++i) {
            const auto bits = static_cast<std::uint64_t>(sums[i * components + c]);
            low[i] = std::bit_cast<float>(static_cast<std::uint32_t>(bits));
            high[i] = std::bit_cast<float>(static_cast<std::uint32_t>(bits >> 32));
        }
    }
}

bool has_exact_sums(const PlaneSet& set, const ChannelInfo& channel) {
    return set.exact_sums && channel.accumulation == film::Accumulation::Sum;
}

const std::vector<float>& plane(const Values& planes, const std::string& name) {
    auto it = planes.find(name);
    if (it == planes.end()) throw std::logic_error("channel " + name + " was not read");
    return it->second;
}

void recover_exact(const ReadPlanes& planes, const ChannelInfo& channel, Sums& sums) {
    const auto components = static_cast<std::size_t>(channel.components);
    for (std::size_t c = 0; c < components; ++c) {
        const auto find = [&](bool high) -> const std::vector<std::uint32_t>& {
            const std::string name = exact_sum_channel_name(channel, static_cast<int>(c), high);
            auto it = planes.exact.find(name);
            if (it == planes.exact.end()) throw std::logic_error("channel " + name + " was not read");
            return it->second;
        };
        const std::vector<std::uint32_t>& low = find(false);
        const std::vector<std::uint32_t>& high = find(true);
        for (std::size_t i = 0; i < low.size(); ++i)
            sums[i * components + c] = static_cast<Sum>((static_cast<std::uint64_t>(high[i]) << 32) | low[i]);
    }
}

// Without exact sums: each sum rebuilt from the stored values, in the
// channel's units, within a float rounding or two.
void recover_means(const Values& planes, const ChannelInfo& channel, const Counts& counts, Sums& sums) {
    const int components = channel.components;
    for (int c = 0; c < components; ++c) {
        const auto& means = plane(planes, channel.exr_names[c]);
        for (std::size_t i = 0; i < means.size(); ++i)
            sums[i * components + c] = film::sum_units(channel.units, static_cast<double>(means[i]) * counts.at(i));
    }
}

void recover_unit_vector(const Values& planes, const ChannelInfo& channel, const Counts& counts, Sums& sums) {
    const int components = channel.components;
    const auto& length = plane(planes, channel.exr_names[components]);
    for (int c = 0; c < components; ++c) {
        const auto& unit = plane(planes, channel.exr_names[c]);
        for (std::size_t i = 0; i < unit.size(); ++i)
            sums[i * components + c] =
                film::sum_units(channel.units, static_cast<double>(unit[i]) * length[i] * counts.at(i));
    }
}

// sum_sq = n ((n-1) var + mean^2), from the paired channel's stored mean.
void recover_second_moment(const Values& planes, const ChannelInfo& channel, const Counts& counts, Sums& sums_sq) {
    const ChannelInfo& paired = film::info(channel.paired);
    const int components = channel.components;
    for (int c = 0; c < components; ++c) {
        const auto& variance = plane(planes, channel.exr_names[c]);
        const auto& mean = plane(planes, paired.exr_names[c]);
        for (std::size_t i = 0; i < variance.size(); ++i) {
            const double n = counts.at(i);
            const double m = mean[i];
            sums_sq[i * components + c] =
                film::sum_units(channel.units, n * ((n - 1.0) * static_cast<double>(variance[i]) + m * m));
        }
    }
}

void recover_values(const Values& planes, const ChannelInfo& channel, Film& film) {
    const int components = channel.components;
    for (int c = 0; c < components; ++c) {
        const auto& stored = plane(planes, channel.exr_names[c]);
        if (channel.accumulation == film::Accumulation::Sum) {
            Sums& sums = film.sums(channel.channel);
            for (std::size_t i = 0; i < stored.size(); ++i)
                sums[i * components + c] = film::sum_units(channel.units, stored[i]);
        } else {
            std::vector<float>& values = film.values(channel.channel);
            for (std::size_t i = 0; i < stored.size(); ++i) values[i * components + c] = stored[i];
        }
    }
}

// Exact sums must give the stored values back bit for bit: otherwise the
// image was changed after orb-render wrote it (its means edited, its
// channels copied from another render), and continuing it would not be
// the render its means show.
// (A variance stored without the layer of its mean cannot be checked: the
// file holds no sums of that mean; such a file does not continue either.)
void check_exact_sums_match(const ReadPlanes& planes, const PlaneSet& set, const Film& film) {
    std::vector<float> storage;
    const std::vector<Plane> expected = film_to_planes(film, PlaneSet{set.passes, false}, storage);
    std::vector<std::string> unchecked;
    for (Pass pass : set.passes)
        for (const ChannelInfo* channel : pass_film_channels(pass))
            if (channel->stored_as == StoredAs::VarianceOfMean && !contains(set.passes, film::info(channel->paired).layer))
                for (int c = 0; c < channel->exr_name_count; ++c) unchecked.push_back(channel->exr_names[c]);
    for (const Plane& p : expected) {
        if (std::find(unchecked.begin(), unchecked.end(), p.name) != unchecked.end()) continue;
        const std::vector<float>& stored = plane(planes.values, p.name);
        for (std::size_t i = 0; i < stored.size(); ++i) {
            if (std::bit_cast<std::uint32_t>(stored[i]) == std::bit_cast<std::uint32_t>(p.values[i])) continue;
            const auto width = static_cast<std::size_t>(film.width);
            throw std::invalid_argument("its exact sums (orb.sum.*) do not give channel " + p.name + " at pixel (" +
                                        std::to_string(i % width) + ", " + std::to_string(i / width) +
                                        "): the image was changed after orb-render wrote it");
        }
    }
}

}  // namespace

std::size_t plane_count(const PlaneSet& set) {
    std::size_t count = 0;
    for (Pass pass : set.passes)
        for (const ChannelInfo* channel : pass_film_channels(pass)) {
            count += static_cast<std::size_t>(channel->exr_name_count);
            if (has_exact_sums(set, *channel)) count += 2 * static_cast<std::size_t>(channel->components);
        }
    return count;
}

std::vector<Plane> plane_layout(const Film& film, const PlaneSet& set, std::vector<float>& storage) {
    const std::size_t pixels = static_cast<std::size_t>(film.width) * static_cast<std::size_t>(film.height);
    if (storage.size() < plane_count(set) * pixels) storage.resize(plane_count(set) * pixels);
    std::vector<Plane> planes;
    const auto next_values = [&] { return std::span<float>(storage.data() + planes.size() * pixels, pixels); };
    for (Pass pass : set.passes)
        for (const ChannelInfo* channel : pass_film_channels(pass)) {
            for (int c = 0; c < channel->exr_name_count; ++c) {
                // Values kept as they are (and the unit vector's length) stay FLOAT under --half.
                const bool always_float = channel->stored_as == StoredAs::Value ||
                                          (channel->stored_as == StoredAs::UnitVector && c == channel->components);
                planes.push_back({channel->exr_names[c], always_float, false, next_values()});
            }
            if (!has_exact_sums(set, *channel)) continue;
            for (int c = 0; c < channel->components; ++c)
                for (bool high : {false, true})
                    planes.push_back({exact_sum_channel_name(*channel, c, high), true, true, next_values()});
        }
    return planes;
}

void fill_planes(const Film& film, const PlaneSet& set, const std::vector<Plane>& planes, std::size_t first,
                 std::size_t end) {
    if (film.samples_per_pixel == 0) throw std::invalid_argument("the film holds no samples");
    const Counts n = film_counts(film, set.passes);
    std::size_t next = 0;  // the planes come in plane_layout's order
    for (Pass pass : set.passes) {
        for (const ChannelInfo* channel : pass_film_channels(pass)) {
            const auto components = static_cast<std::size_t>(channel->components);
            switch (channel->stored_as) {
                case StoredAs::Mean:
                    mean_channel(*channel, film.sums(channel->channel), n,
                                 std::span(planes).subspan(next, components), first, end);
                    next += components;
                    break;
                case StoredAs::UnitVector:
                    unit_vector_planes(*channel, film.sums(channel->channel), n,
                                       std::span(planes).subspan(next, components + 1), first, end);
                    next += components + 1;
                    break;
                case StoredAs::VarianceOfMean:
                    for (std::size_t c = 0; c < components; ++c)
                        variance_channel(*channel, film.sums(channel->paired), film.sums(channel->channel),
                                         static_cast<int>(c), n, planes[next++].values, first, end);
                    break;
                case StoredAs::Value:
                    for (std::size_t c = 0; c < components; ++c)
                        component_values(film, *channel, static_cast<int>(c), planes[next++].values, first, end);
                    break;
            }
            if (!has_exact_sums(set, *channel)) continue;
            exact_planes(*channel, film.sums(channel->channel), std::span(planes).subspan(next, 2 * components),
                         first, end);
            next += 2 * components;
        }
    }
}

std::vector<Plane> film_to_planes(const Film& film, const PlaneSet& set, std::vector<float>& storage) {
    if (film.samples_per_pixel == 0) throw std::invalid_argument("the film holds no samples");
    std::vector<Plane> planes = plane_layout(film, set, storage);
    fill_planes(film, set, planes, 0, static_cast<std::size_t>(film.width) * static_cast<std::size_t>(film.height));
    return planes;
}

void planes_to_film(const ReadPlanes& planes, const PlaneSet& set, Film& film) {
    const std::vector<Pass>& passes = set.passes;
    // The pixels' own counts first: every mean is over them.
    const ChannelInfo& count_channel = film::info(film::Channel::sample_count);
    if (!contains(passes, film::Layer::Samples))  // every pixel holds the film's samples
        film.sample_count.assign(film.pixel_count(), static_cast<Sum>(film.samples_per_pixel));
    else if (set.exact_sums)
        recover_exact(planes, count_channel, film.sample_count);
    else
        recover_values(planes.values, count_channel, film);
    const Counts n = film_counts(film, passes);
    for (Pass pass : passes) {
        for (const ChannelInfo* channel : pass_film_channels(pass)) {
            if (channel->channel == film::Channel::sample_count) continue;  // done above
            if (has_exact_sums(set, *channel)) {
                recover_exact(planes, *channel, film.sums(channel->channel));
                continue;
            }
            switch (channel->stored_as) {
                case StoredAs::Mean: recover_means(planes.values, *channel, n, film.sums(channel->channel)); break;
                case StoredAs::UnitVector:
                    recover_unit_vector(planes.values, *channel, n, film.sums(channel->channel));
                    break;
                case StoredAs::VarianceOfMean:
                    // Needs the paired channel's mean, from its own pass.
                    if (contains(passes, film::info(channel->paired).layer))
                        recover_second_moment(planes.values, *channel, n, film.sums(channel->channel));
                    break;
                case StoredAs::Value: recover_values(planes.values, *channel, film); break;
            }
        }
    }
    if (set.exact_sums) check_exact_sums_match(planes, set, film);
}

}  // namespace orb::exr::detail
