#include "scene_saving.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "errors.h"
#include "orb/cli/map_paths.h"
#include "orb/cli/output_file.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"

namespace orb::python {

void save_scene(const Scene& scene, const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".orb" && extension != ".json")
        throw_value_error(path + ": expected a .json (Orb JSON) or .orb (binary scene) name");
    cli::OutputFile output(path, "path");
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    const std::string folder = parent.empty() ? std::string(".") : parent.string();
    const auto write = [&](const Scene& written) {
        output.write(extension == ".orb" ? write_scene_binary(written) : write_scene_json(written));
    };
    if (scene.environment.kind != EnvironmentKind::Map) return write(scene);
    Scene rebased = scene;  // the map's path as seen from the file's folder
    cli::rebase_environment_map(rebased, ".", folder);
    write(rebased);
}

}  // namespace orb::python
