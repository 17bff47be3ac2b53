#include "orb/image/passes.h"

#include "orb/tables/film_channels.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <set>

namespace orb::image {
namespace {

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Finds a channel by case-insensitive name.
int find_ci(const Image& image, const std::string& name) {
    const std::string wanted = lower(name);
    for (int c = 0; c < image.channels(); ++c)
        if (lower(image.channel_names[c]) == wanted) return c;
    return -1;
}

// Finds "<layer>.<one of suffixes>" for each wanted component.
std::optional<std::vector<int>> find_group(const Image& image, const std::vector<std::string>& layers,
                                           const std::vector<std::vector<std::string>>& components) {
    for (const std::string& layer : layers) {
        std::vector<int> found;
        for (const auto& alternatives : components) {
            int index = -1;
            for (const std::string& suffix : alternatives) {
                index = find_ci(image, layer.empty() ? suffix : layer + "." + suffix);
                if (index >= 0) break;
            }
            if (index < 0) break;
            found.push_back(index);
        }
        if (found.size() == components.size()) return found;
    }
    return std::nullopt;
}

const std::vector<std::vector<std::string>> kRGB = {{"R", "r", "red"}, {"G", "g", "green"}, {"B", "b", "blue"}};
const std::vector<std::vector<std::string>> kXYZ = {{"X", "x", "R"}, {"Y", "y", "G"}, {"Z", "z", "B"}};

bool is_layered(const std::string& channel) { return channel.find('.') != std::string::npos; }

std::optional<Pass> find_pass(const Image& image, const std::string& requested) {
    const std::string name = lower(requested);
    Pass pass;
    if (name == "beauty" || name == "rgba" || name == "rgb") {
        pass.name = "beauty";
        pass.kind = PassKind::Color;
        if (auto rgb = find_group(image, {""}, kRGB)) {
            std::vector<int> idx = *rgb;
            std::vector<std::string> names = {"R", "G", "B"};
            if (int a = find_ci(image, "A"); a >= 0) {
                idx.push_back(a);
                names.push_back("A");
                pass.has_alpha = true;
            }
            pass.image = select_channels(image, idx, names);
            return pass;
        }
        // Greyscale files ("Y" or a lone unnamed channel, maybe with alpha).
        std::vector<int> plain;
        for (int c = 0; c < image.channels(); ++c)
            if (!is_layered(image.channel_names[c])) plain.push_back(c);
        if (!plain.empty() && plain.size() <= 2) {
            int luminance = plain[0];
            int alpha = -1;
            if (plain.size() == 2) {
                if (lower(image.channel_names[plain[0]]) == "a") std::swap(plain[0], plain[1]);
                luminance = plain[0];
                alpha = plain[1];
            }
            std::vector<int> idx = {luminance, luminance, luminance};
            std::vector<std::string> names = {"R", "G", "B"};
            if (alpha >= 0) {
                idx.push_back(alpha);
                names.push_back("A");
                pass.has_alpha = true;
            }
            pass.image = select_channels(image, idx, names);
            return pass;
        }
        return std::nullopt;
    }
    if (name == "normal" || name == "n") {
        pass.name = "normal";
        pass.kind = PassKind::Normal;
        auto xyz = find_group(image, {"N", "normal", "normals"}, kXYZ);
        if (!xyz) return std::nullopt;
        pass.image = select_channels(image, *xyz, {"X", "Y", "Z"});
        return pass;
    }
    if (name == "depth" || name == "z") {
        pass.name = "depth";
        pass.kind = PassKind::Depth;
        for (const char* candidate : {"Z", "depth.Z", "depth.V", "depth.Y", "depth"}) {
            if (int c = find_ci(image, candidate); c >= 0) {
                pass.image = select_channels(image, {c}, {"Z"});
                return pass;
            }
        }
        return std::nullopt;
    }
    if (name == "id") {
        pass.name = "id";
        pass.kind = PassKind::Id;
        for (const char* candidate : {"id", "id.V", "id.id", "id.R", "objectid", "object_id"}) {
            if (int c = find_ci(image, candidate); c >= 0) {
                pass.image = select_channels(image, {c}, {"id"});
                return pass;
            }
        }
        return std::nullopt;
    }
    // Colour layers (direct, indirect, emission, albedo, variance, others).
    pass.name = requested;
    if (auto rgb = find_group(image, {requested}, kRGB)) {
        pass.kind = kind_of_pass(name);
        pass.image = select_channels(image, *rgb, {"R", "G", "B"});
        return pass;
    }
    // Any other layer: all of its channels, as data.
    std::vector<int> idx;
    std::vector<std::string> names;
    const std::string prefix = lower(requested) + ".";
    for (int c = 0; c < image.channels(); ++c) {
        const std::string ch = lower(image.channel_names[c]);
        if (ch.rfind(prefix, 0) == 0) {
            idx.push_back(c);
            names.push_back(image.channel_names[c].substr(prefix.size()));
        }
    }
    if (idx.empty()) return std::nullopt;
    pass.kind = PassKind::Data;
    pass.image = select_channels(image, idx, names);
    return pass;
}

}  // namespace

// orb-render's layers and their kinds: the film's channel table
// (libtables/include/orb/tables/film_channels.h).
const std::vector<std::string>& canonical_pass_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> list;
        for (const film::LayerInfo& layer : film::kLayers) list.push_back(layer.name);
        for (const film::PostLayerInfo& layer : film::kPostLayers) list.push_back(layer.name);
        return list;
    }();
    return names;
}

namespace {

PassKind pass_kind(film::LayerKind kind) {
    switch (kind) {
        case film::LayerKind::Color: return PassKind::Color;
        case film::LayerKind::Normal: return PassKind::Normal;
        case film::LayerKind::Depth: return PassKind::Depth;
        case film::LayerKind::Id: return PassKind::Id;
        case film::LayerKind::Variance: return PassKind::Variance;
        case film::LayerKind::Count: return PassKind::Data;
    }
    return PassKind::Data;
}

}  // namespace

PassKind kind_of_pass(const std::string& canonical_name) {
    const std::string n = lower(canonical_name);
    for (const film::LayerInfo& layer : film::kLayers)
        if (n == layer.name) return pass_kind(layer.kind);
    for (const film::PostLayerInfo& layer : film::kPostLayers)
        if (n == layer.name) return pass_kind(layer.kind);
    return PassKind::Color;  // a colour layer of another renderer's file
}

const char* kind_name(PassKind kind) {
    switch (kind) {
        case PassKind::Color: return "color";
        case PassKind::Normal: return "normal";
        case PassKind::Depth: return "depth";
        case PassKind::Id: return "id";
        case PassKind::Variance: return "variance";
        case PassKind::Data: return "data";
    }
    return "data";
}

std::vector<std::string> available_passes(const Image& image) {
    std::vector<std::string> result;
    std::set<std::string> claimed_layers;  // lower-case layer names already covered
    for (const std::string& name : canonical_pass_names()) {
        if (find_pass(image, name)) {
            result.push_back(name);
            claimed_layers.insert(name);
        }
    }
    claimed_layers.insert("n");
    claimed_layers.insert("normals");
    for (const std::string& channel : image.channel_names) {
        // orb-render's own bookkeeping (orb.normalLength, the exact sums
        // orb.sum.R.lo, ...), not a picture.
        if (lower(channel).rfind("orb.", 0) == 0) continue;
        const auto dot = channel.rfind('.');
        if (dot == std::string::npos) continue;
        const std::string layer = channel.substr(0, dot);
        if (claimed_layers.insert(lower(layer)).second) result.push_back(layer);
    }
    return result;
}

Pass extract_pass(const Image& image, const std::string& pass, const std::string& source) {
    if (auto found = find_pass(image, pass)) return std::move(*found);
    std::string have;
    for (const std::string& p : available_passes(image)) have += (have.empty() ? "" : ", ") + p;
    throw PassMissing(source + ": no '" + pass + "' pass (the image has: " + (have.empty() ? "none" : have) + ")");
}

}  // namespace orb::image
