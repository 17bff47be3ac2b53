#include "orb/cli/legend_output.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>

#include "orb/cli/messages.h"
#include "orb/cli/paths.h"
#include "orb/scene/error.h"

namespace orb::cli {
namespace {

using EncodeEntry = bool (*)(const ColorLegend&, bool, std::string&, std::string&);

struct LoadedModule {
    EncodeEntry encode = nullptr;
    std::string path;
    std::string why_not;  // set when encode is null
};

// Loaded once per process and never unloaded (OpenImageIO's state may outlive a call).
const LoadedModule& legend_module() {
    static LoadedModule loaded;
    static std::once_flag once;
    std::call_once(once, [] {
        const std::filesystem::path bin = std::filesystem::path(executable_path()).parent_path();
        loaded.path = (bin.parent_path() / "lib" / "orb" / "orb_legend.so").string();
        void* handle = dlopen(loaded.path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* error = dlerror();
            loaded.why_not = error ? error : "dlopen failed";
            return;
        }
        loaded.encode = reinterpret_cast<EncodeEntry>(dlsym(handle, "orb_encode_legend_v1"));
        if (!loaded.encode) loaded.why_not = loaded.path + ": no entry point orb_encode_legend_v1";
    });
    return loaded;
}

}  // namespace

std::optional<LegendOutput> LegendOutput::prepare(const SphereStyleArguments& arguments,
                                                  const std::vector<NamedPath>& inputs) {
    if (arguments.legend.empty()) return std::nullopt;
    refuse_overlapping_paths(inputs, {{"--legend", arguments.legend}});
    return LegendOutput(OutputFile(arguments.legend, "--legend"), arguments.legend_layout == "horizontal");
}

void LegendOutput::write(const SphereStyleResult& styled, const std::string& source, bool frames_differ) {
    if (!styled.legend) throw InputError(source + ": --legend: nothing was coloured by --color-by");
    const LoadedModule& module = legend_module();
    if (!module.encode)
        throw InputError(file_.display_name() + ": --legend: the legend writer (OpenImageIO) did not load (" +
                         module.why_not + ")");
    std::string png, error;
    if (!module.encode(*styled.legend, horizontal_, png, error))
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
