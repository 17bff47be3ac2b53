#include "output_format.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "orb/cli/tool_main.h"

namespace orb::import_tool {

OutputFormat choose_output_format(const std::string& to, const std::string& output) {
    if (to == "scn") return OutputFormat::Scn;
    if (to == "orb-binary") return OutputFormat::OrbBinary;
    if (!to.empty()) return OutputFormat::OrbJson;  // "orb" or "json"

    std::string extension = std::filesystem::path(output).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".scn") return OutputFormat::Scn;
    if (extension == ".orb") return OutputFormat::OrbBinary;
    if (extension == ".gltf" || extension == ".glb")
        throw cli::UsageError(output + ": orb-import writes Orb JSON, the binary .orb or .scn, not glTF; name the "
                                       "output .json, .orb or .scn, or pass --to");
    return OutputFormat::OrbJson;
}

}  // namespace orb::import_tool
