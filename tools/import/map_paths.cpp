#include "map_paths.h"

#include <filesystem>

namespace orb::import_tool {

void rebase_environment_map(Scene& scene, const std::string& input_dir, const std::string& output_dir) {
    namespace fs = std::filesystem;
    Environment& environment = scene.environment;
    if (environment.kind != EnvironmentKind::Map || fs::path(environment.map).is_absolute()) return;
    const fs::path file = (fs::absolute(input_dir) / environment.map).lexically_normal();
    const fs::path from_output = file.lexically_relative(fs::absolute(output_dir).lexically_normal());
    // No relative path between them (another drive on Windows): keep the file absolute.
    environment.map = (from_output.empty() ? file : from_output).generic_string();
}

}  // namespace orb::import_tool
