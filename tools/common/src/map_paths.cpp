#include "orb/cli/map_paths.h"

#include <filesystem>

namespace orb::cli {

std::string rebased_map_path(const std::string& map, const std::string& input_dir, const std::string& output_dir) {
    namespace fs = std::filesystem;
    if (fs::path(map).is_absolute()) return map;
    const fs::path file = (fs::absolute(input_dir) / map).lexically_normal();
    const fs::path from_output = file.lexically_relative(fs::absolute(output_dir).lexically_normal());
    // No relative path between them (another drive on Windows): keep the file absolute.
    return (from_output.empty() ? file : from_output).generic_string();
}

void rebase_environment_map(Scene& scene, const std::string& input_dir, const std::string& output_dir) {
    Environment& environment = scene.environment;
    if (environment.kind == EnvironmentKind::Map)
        environment.map = rebased_map_path(environment.map, input_dir, output_dir);
}

}  // namespace orb::cli
