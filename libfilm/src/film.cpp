#include "orb/film/film.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace orb {
namespace {

using SumMember = std::vector<film::Sum> Film::*;
using ValueMember = std::vector<float> Film::*;

// Each channel's member: a Sum channel's in kSumMembers, a CentreRay
// channel's in kValueMembers, at the channel's index (null in the other).
#define ORB_FILM_SUM_POINTER_Sum(name) &Film::name
#define ORB_FILM_SUM_POINTER_CentreRay(name) nullptr
#define ORB_FILM_SUM_POINTER(name, components, clear, accumulate, ...) ORB_FILM_SUM_POINTER_##accumulate(name),
constexpr SumMember kSumMembers[] = {ORB_FILM_CHANNELS(ORB_FILM_SUM_POINTER)};
#undef ORB_FILM_SUM_POINTER
#undef ORB_FILM_SUM_POINTER_Sum
#undef ORB_FILM_SUM_POINTER_CentreRay

#define ORB_FILM_VALUE_POINTER_Sum(name) nullptr
#define ORB_FILM_VALUE_POINTER_CentreRay(name) &Film::name
#define ORB_FILM_VALUE_POINTER(name, components, clear, accumulate, ...) ORB_FILM_VALUE_POINTER_##accumulate(name),
constexpr ValueMember kValueMembers[] = {ORB_FILM_CHANNELS(ORB_FILM_VALUE_POINTER)};
#undef ORB_FILM_VALUE_POINTER
#undef ORB_FILM_VALUE_POINTER_Sum
#undef ORB_FILM_VALUE_POINTER_CentreRay

static_assert(std::size(kSumMembers) == film::kChannels.size() && std::size(kValueMembers) == film::kChannels.size());

bool is_sum(film::Channel channel) { return film::info(channel).accumulation == film::Accumulation::Sum; }

[[noreturn]] void wrong_kind(film::Channel channel, const char* asked)
{
    throw std::logic_error(std::string("film channel ") + film::info(channel).name + " holds no " + asked);
}

}  // namespace

std::vector<film::Sum>& Film::sums(film::Channel c)
{
    if (!is_sum(c)) wrong_kind(c, "sums");
    return this->*kSumMembers[static_cast<int>(c)];
}
const std::vector<film::Sum>& Film::sums(film::Channel c) const
{
    if (!is_sum(c)) wrong_kind(c, "sums");
    return this->*kSumMembers[static_cast<int>(c)];
}
std::vector<float>& Film::values(film::Channel c)
{
    if (is_sum(c)) wrong_kind(c, "float values");
    return this->*kValueMembers[static_cast<int>(c)];
}
const std::vector<float>& Film::values(film::Channel c) const
{
    if (is_sum(c)) wrong_kind(c, "float values");
    return this->*kValueMembers[static_cast<int>(c)];
}

std::span<std::byte> Film::bytes(film::Channel c)
{
    if (is_sum(c)) return std::as_writable_bytes(std::span(sums(c)));
    return std::as_writable_bytes(std::span(values(c)));
}
std::span<const std::byte> Film::bytes(film::Channel c) const
{
    if (is_sum(c)) return std::as_bytes(std::span(sums(c)));
    return std::as_bytes(std::span(values(c)));
}
std::size_t Film::entries(film::Channel c) const { return is_sum(c) ? sums(c).size() : values(c).size(); }

void Film::resize(int w, int h, std::uint32_t channels)
{
    if (w < 0 || h < 0) throw std::invalid_argument("film size must not be negative");
    width = w;
    height = h;
    samples_per_pixel = 0;
    sample_ranges = {};
    for (const film::ChannelInfo& info : film::kChannels) {
        const bool held = (channels & film::channel_bit(info.channel)) != 0;
        const std::size_t count = held ? pixel_count() * static_cast<std::size_t>(info.components) : 0;
        // A channel not held gives its memory back.
        if (is_sum(info.channel)) {
            std::vector<film::Sum>& sums_of = sums(info.channel);
            if (held) sums_of.assign(count, 0); else std::vector<film::Sum>().swap(sums_of);
        } else {
            std::vector<float>& values_of = values(info.channel);
            if (held) values_of.assign(count, info.clear); else std::vector<float>().swap(values_of);
        }
    }
}

SampleRanges Film::held_ranges() const
{
    if (!sample_ranges.empty() || samples_per_pixel == 0) return sample_ranges;
    return SampleRanges(SampleRange{0, samples_per_pixel});
}

void Film::accumulate(const Film& other, std::uint32_t channels)
{
    if (other.width != width || other.height != height)
        throw std::invalid_argument("cannot add a " + std::to_string(other.width) + "x" + std::to_string(other.height) +
                                    " film to a " + std::to_string(width) + "x" + std::to_string(height) + " one");
    if (other.samples_per_pixel == 0) return;
    SampleRanges ranges = held_ranges();
    const SampleRanges others = other.held_ranges();
    ranges.add(others);  // throws for overlapping samples
    if (ranges.total() > film::kMaxSamplesPerPixel)
        throw std::invalid_argument("a film holds at most 2^39 samples per pixel; these two hold " +
                                    std::to_string(ranges.total()));

    // The same-in-every-slice channels come from the film with the lowest sample index.
    const bool take_others = samples_per_pixel == 0 || others.first() < held_ranges().first();
    for (const film::ChannelInfo& info : film::kChannels) {
        if ((channels & film::channel_bit(info.channel)) == 0) continue;
        if (entries(info.channel) != other.entries(info.channel))
            throw std::invalid_argument(std::string("film channel ") + info.name + " sizes differ");
        switch (info.merge) {
            case film::MergeRule::Sum: {
                std::vector<film::Sum>& into = sums(info.channel);
                const std::vector<film::Sum>& from = other.sums(info.channel);
                for (std::size_t i = 0; i < into.size(); ++i) into[i] = film::add_sums(into[i], from[i]);
                break;
            }
            case film::MergeRule::Same:
                if (take_others) values(info.channel) = other.values(info.channel);
                break;
        }
    }
    samples_per_pixel += other.samples_per_pixel;
    sample_ranges = std::move(ranges);
}

namespace film {

std::vector<OutOfRange> sums_out_of_range(const Film& film)
{
    std::vector<OutOfRange> found;
    for (const ChannelInfo& info : kChannels) {
        if (info.units != Units::Fixed) continue;
        const std::vector<Sum>& sums = film.sums(info.channel);
        const auto components = static_cast<std::size_t>(info.components);
        OutOfRange out{info.channel, 0, 0};
        for (std::size_t pixel = 0; pixel * components < sums.size(); ++pixel) {
            const auto first = sums.begin() + static_cast<std::ptrdiff_t>(pixel * components);
            if (std::none_of(first, first + static_cast<std::ptrdiff_t>(components),
                             [](Sum s) { return s >= kSumRangeEnd; }))
                continue;
            if (out.pixels++ == 0) out.first_pixel = pixel;
        }
        if (out.pixels > 0) found.push_back(out);
    }
    return found;
}

std::string describe(const OutOfRange& out, int width)
{
    const auto w = static_cast<std::size_t>(std::max(width, 1));
    return std::string("the ") + info(out.channel).name + " sums of " + std::to_string(out.pixels) +
           (out.pixels == 1 ? " pixel" : " pixels") + " (the first at (" + std::to_string(out.first_pixel % w) + ", " +
           std::to_string(out.first_pixel / w) +
           ")) reached the film's range, 2^38 (2.7e11) per pixel: a sample or a sum was clamped there, so those "
           "values are below the mean of their samples";
}

}  // namespace film

}  // namespace orb
