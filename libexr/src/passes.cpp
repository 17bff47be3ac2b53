#include "orb/exr/passes.h"

#include <algorithm>
#include <stdexcept>

namespace orb::exr {

const std::vector<Pass>& all_passes() {
    static const std::vector<Pass> passes = [] {
        std::vector<Pass> list;
        for (const film::LayerInfo& layer : film::kLayers) list.push_back(layer.layer);
        return list;
    }();
    return passes;
}

const std::vector<Pass>& image_passes() {
    static const std::vector<Pass> passes = [] {
        std::vector<Pass> list = all_passes();
        list.erase(std::find(list.begin(), list.end(), film::Layer::Samples));
        return list;
    }();
    return passes;
}

const char* pass_name(Pass pass) { return film::info(pass).name; }

std::vector<const film::ChannelInfo*> pass_film_channels(Pass pass) {
    std::vector<const film::ChannelInfo*> channels;
    for (const film::ChannelInfo& channel : film::kChannels)
        if (channel.layer == pass) channels.push_back(&channel);
    return channels;
}

std::vector<std::string> pass_channels(Pass pass) {
    std::vector<std::string> names;
    for (const film::ChannelInfo* channel : pass_film_channels(pass))
        for (int i = 0; i < channel->shown_exr_names(); ++i) names.push_back(channel->exr_names[i]);
    return names;
}

std::vector<std::string> pass_resume_channels(Pass pass) {
    // N is normalised for viewers; the length of the mean normal (below 1
    // where the pixel straddles an edge or a miss) is what the sum needs back.
    std::vector<std::string> names;
    for (const film::ChannelInfo* channel : pass_film_channels(pass))
        for (int i = channel->shown_exr_names(); i < channel->exr_name_count; ++i)
            names.push_back(channel->exr_names[i]);
    return names;
}

std::string exact_sum_channel_name(const film::ChannelInfo& channel, int component, bool high) {
    std::string name = "orb.sum.";
    name += channel.exr_names[static_cast<std::size_t>(component)];
    name += high ? ".hi" : ".lo";
    return name;
}

std::vector<std::string> pass_exact_sum_channels(Pass pass) {
    std::vector<std::string> names;
    for (const film::ChannelInfo* channel : pass_film_channels(pass)) {
        if (channel->accumulation != film::Accumulation::Sum) continue;
        for (int c = 0; c < channel->components; ++c)
            for (bool high : {false, true}) names.push_back(exact_sum_channel_name(*channel, c, high));
    }
    return names;
}

bool contains(const std::vector<Pass>& passes, Pass pass) {
    return std::find(passes.begin(), passes.end(), pass) != passes.end();
}

std::vector<Pass> parse_passes(const std::string& list) {
    std::vector<Pass> chosen;
    std::size_t start = 0;
    while (start <= list.size()) {
        std::size_t comma = list.find(',', start);
        if (comma == std::string::npos) comma = list.size();
        const std::string item = list.substr(start, comma - start);
        start = comma + 1;
        if (item == "all") {
            for (Pass p : image_passes())
                if (!contains(chosen, p)) chosen.push_back(p);
            continue;
        }
        auto match = std::find_if(all_passes().begin(), all_passes().end(),
                                  [&](Pass p) { return item == pass_name(p); });
        if (match == all_passes().end()) {
            std::string names;
            for (Pass p : all_passes()) names += std::string(names.empty() ? "" : ",") + pass_name(p);
            throw std::invalid_argument("unknown pass '" + item + "' (expected a comma-separated list of " + names +
                                        ", or all)");
        }
        if (!contains(chosen, *match)) chosen.push_back(*match);
    }
    std::vector<Pass> ordered;
    for (Pass p : all_passes())
        if (contains(chosen, p)) ordered.push_back(p);
    return ordered;
}

std::string format_passes(const std::vector<Pass>& passes) {
    std::string text;
    for (Pass p : passes) text += std::string(text.empty() ? "" : ",") + pass_name(p);
    return text;
}

}  // namespace orb::exr
