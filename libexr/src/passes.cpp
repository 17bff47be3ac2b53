#include "orb/exr/passes.h"

#include <algorithm>
#include <stdexcept>

namespace orb::exr {

const std::vector<Pass>& all_passes() {
    static const std::vector<Pass> passes{Pass::Beauty, Pass::Direct, Pass::Indirect, Pass::Emission, Pass::Albedo,
                                          Pass::Normal, Pass::Depth,  Pass::Variance, Pass::Id};
    return passes;
}

const char* pass_name(Pass pass) {
    switch (pass) {
        case Pass::Beauty: return "beauty";
        case Pass::Direct: return "direct";
        case Pass::Indirect: return "indirect";
        case Pass::Emission: return "emission";
        case Pass::Albedo: return "albedo";
        case Pass::Normal: return "normal";
        case Pass::Depth: return "depth";
        case Pass::Variance: return "variance";
        case Pass::Id: return "id";
    }
    return "?";
}

std::vector<std::string> pass_channels(Pass pass) {
    auto rgb = [](const std::string& layer) {
        return std::vector<std::string>{layer + ".R", layer + ".G", layer + ".B"};
    };
    switch (pass) {
        case Pass::Beauty: return {"R", "G", "B", "A"};
        case Pass::Direct: return rgb("direct");
        case Pass::Indirect: return rgb("indirect");
        case Pass::Emission: return rgb("emission");
        case Pass::Albedo: return rgb("albedo");
        case Pass::Normal: return {"N.X", "N.Y", "N.Z"};
        case Pass::Depth: return {"Z"};
        case Pass::Variance: return rgb("variance");
        case Pass::Id: return {"id"};
    }
    return {};
}

std::vector<std::string> pass_resume_channels(Pass pass) {
    // N is normalised for viewers; the length of the mean normal (below 1
    // where the pixel straddles an edge or a miss) is what the sum needs back.
    if (pass == Pass::Normal) return {"orb.normalLength"};
    return {};
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
            chosen = all_passes();
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
