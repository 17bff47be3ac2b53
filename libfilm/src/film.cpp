#include "orb/film/film.h"

#include <stdexcept>
#include <string>

namespace orb {
namespace {

using Member = std::vector<float> Film::*;

constexpr Member kMembers[] = {
#define ORB_FILM_MEMBER_POINTER(name, ...) &Film::name,
    ORB_FILM_CHANNELS(ORB_FILM_MEMBER_POINTER)
#undef ORB_FILM_MEMBER_POINTER
};
static_assert(std::size(kMembers) == film::kChannels.size());

}  // namespace

std::vector<float>& Film::channel(film::Channel c) { return this->*kMembers[static_cast<int>(c)]; }
const std::vector<float>& Film::channel(film::Channel c) const { return this->*kMembers[static_cast<int>(c)]; }

void Film::resize(int w, int h, std::uint32_t channels)
{
    if (w < 0 || h < 0) throw std::invalid_argument("film size must not be negative");
    width = w;
    height = h;
    samples_per_pixel = 0;
    sample_ranges = {};
    for (const film::ChannelInfo& info : film::kChannels) {
        std::vector<float>& values = channel(info.channel);
        if ((channels & film::channel_bit(info.channel)) == 0) {
            std::vector<float>().swap(values);  // its memory given back
            continue;
        }
        values.assign(pixel_count() * static_cast<std::size_t>(info.components), info.clear);
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

    // The same-in-every-slice channels come from the film with the lowest sample index.
    const bool take_others = samples_per_pixel == 0 || others.first() < held_ranges().first();
    for (const film::ChannelInfo& info : film::kChannels) {
        if ((channels & film::channel_bit(info.channel)) == 0) continue;
        std::vector<float>& into = channel(info.channel);
        const std::vector<float>& from = other.channel(info.channel);
        if (into.size() != from.size())
            throw std::invalid_argument(std::string("film channel ") + info.name + " sizes differ");
        switch (info.merge) {
            case film::MergeRule::Sum:
                for (std::size_t i = 0; i < into.size(); ++i) into[i] += from[i];
                break;
            case film::MergeRule::Same:
                if (take_others) into = from;
                break;
        }
    }
    samples_per_pixel += other.samples_per_pixel;
    sample_ranges = std::move(ranges);
}

}  // namespace orb
