// Orb's run-time modules: shared libraries installed beside the tools
// (PREFIX/lib/orb/NAME.so) that carry what a tool must not link, such as
// OpenImageIO for orb-render (docs/design/texture-decoding.md). Each is
// opened once per process, on first use, and never closed: state made by
// the module (decoded texels, OpenImageIO's own) may outlive any one call.
#pragma once

#include <string>

namespace orb::cli {

struct RuntimeModule {
    void* entry = nullptr;  // the entry point's address, null when the module or the entry is missing
    std::string path;       // where the module was looked for
    std::string why_not;    // set when entry is null
};

// The module `file_name` in `folder` and its entry point `entry_point`,
// loaded on the first call for that file and remembered. The tools' folder is
// tools_module_folder(); the Python module keeps its own beside itself.
const RuntimeModule& runtime_module(const std::string& folder, const std::string& file_name,
                                    const std::string& entry_point);

// The tools' folder of modules: <dir of executable>/../lib/orb.
std::string tools_module_folder();

// runtime_module in tools_module_folder().
const RuntimeModule& runtime_module(const std::string& file_name, const std::string& entry_point);

}  // namespace orb::cli
