#include "orb/cli/legend_output.h"

#include "orb/cli/messages.h"
#include "orb/cli/paths.h"
#include "orb/cli/runtime_module.h"
#include "orb/scene/error.h"

namespace orb::cli {
namespace {

using EncodeEntry = bool (*)(const ColorLegend&, bool, std::string&, std::string&);

}  // namespace

std::optional<LegendOutput> LegendOutput::prepare(const SphereStyleArguments& arguments,
                                                  const std::vector<NamedPath>& inputs) {
    if (arguments.legend.empty()) return std::nullopt;
    refuse_overlapping_paths(inputs, {{"--legend", arguments.legend}});
    return LegendOutput(OutputFile(arguments.legend, "--legend"), arguments.legend_layout == "horizontal");
}

void LegendOutput::write(const SphereStyleResult& styled, const std::string& source, bool frames_differ) {
    if (!styled.legend) throw InputError(source + ": --legend: nothing was coloured by --color-by");
    const RuntimeModule& module = runtime_module("orb_legend.so", "orb_encode_legend_v1");
    if (!module.entry)
        throw InputError(file_.display_name() + ": --legend: the legend writer (OpenImageIO) did not load (" +
                         module.why_not + ")");
    const auto encode = reinterpret_cast<EncodeEntry>(module.entry);
    std::string png, error;
    if (!encode(*styled.legend, horizontal_, png, error))
        throw InputError(file_.display_name() + ": --legend: " + error);
    try {
        file_.write(png);
    } catch (const std::exception& e) {
        throw InputError(e.what());
    }
    const ColorLegend& legend = *styled.legend;
    std::string what = legend.categorical ? std::to_string(legend.categories.size()) + " categories of " + legend.property
                                          : legend.property + " over " + colormap_name(legend.colormap);
    if (frames_differ)
        what += legend.categorical ? ", as frame 1 has them"
                                   : ", the range of frame 1 (each frame takes its own range unless --color-range fixes one)";
    info(file_.display_name() + ": legend of " + what);
}

}  // namespace orb::cli
