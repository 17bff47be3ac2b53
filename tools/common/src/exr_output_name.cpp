#include "orb/cli/exr_output_name.h"

#include <cctype>
#include <filesystem>

#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/cli/tool_main.h"

namespace orb::cli {

void require_exr_output_name(const std::string& output) {
    std::string extension = std::filesystem::path(output).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (is_stdio(output) || extension.empty() || extension == ".exr") return;
    const std::string stem = std::filesystem::path(output).replace_extension(".exr").string();
    throw UsageError("-o " + output + ": " + tool_name() + " writes OpenEXR only; write " + stem +
                     " and convert it with orb-tonemap (orb-tonemap " + stem + " -o " + output + ")");
}

}  // namespace orb::cli
