#include "orb/request/scene_input.h"

#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/exr/environment_map.h"
#include "orb/job/scene_pose.h"
#include "orb/scene/animation.h"
#include "orb/import/import.h"
#include "orb/import/importers.h"
#include "orb/import/molecular.h"
#include "orb/scene/error.h"
#include "orb/import/numbered_series.h"
#include "orb/scene/scene_json.h"

namespace orb::request {

namespace fs = std::filesystem;

namespace {

// Where a scene's relative paths (glTF buffers, environment maps) are resolved from.
std::string scene_folder(const std::string& path) {
    return cli::is_stdio(path) ? fs::current_path().string() : fs::absolute(path).parent_path().string();
}

// The environment --environment chooses, its map loaded (resolved from the
// scene's folder, as a map the scene names is); nothing when none was chosen.
std::optional<Environment> chosen_environment(const cli::SceneReading& reading, const std::string& base_dir,
                                              const std::string& label) {
    std::optional<Environment> chosen = cli::chosen_environment(reading.environment, base_dir);
    if (!chosen) return std::nullopt;
    Scene holder;
    holder.environment = std::move(*chosen);
    exr::load_environment_map(holder, base_dir, label);
    return std::move(holder.environment);
}

// A trajectory whose every frame is lit by the environment chosen on the command line.
class EnvironmentLitFrames final : public FrameSource {
public:
    EnvironmentLitFrames(std::unique_ptr<FrameSource> frames, Environment environment)
        : frames_(std::move(frames)), environment_(std::move(environment)) {}
    std::size_t frame_count() const override { return frames_->frame_count(); }
    Scene frame(std::size_t index) const override {
        Scene scene = frames_->frame(index);
        scene.environment = environment_;  // the map's texels are shared, not copied
        return scene;
    }
    const std::vector<std::string>& warnings() const override { return frames_->warnings(); }
    std::string_view format() const override { return frames_->format(); }
    std::size_t frames_built() const override { return frames_->frames_built(); }

private:
    std::unique_ptr<FrameSource> frames_;
    Environment environment_;
};

}  // namespace

Scene read_scene(const std::string& path, std::string& label, const cli::SceneReading& reading) {
    label = cli::is_stdio(path) ? "<stdin>" : path;
    const std::string base_dir = scene_folder(path);
    // Checked before the scene, which may be millions of spheres, is read.
    std::optional<Environment> environment = chosen_environment(reading, base_dir, label);
    const std::string bytes = cli::read_input(path);
    ImportResult imported = import_scene(bytes, label, base_dir, cli::import_options_for(reading));
    cli::warn_about_other_formats_options(reading, imported.format, label);
    for (const std::string& message : imported.warnings) cli::warning(message);
    for (const std::string& message : imported.notices) cli::warning(message);
    if (environment) {
        imported.scene.environment = std::move(*environment);
    } else {
        // The map's texels join the scene before it is hashed (they are part of its identity) and rendered.
        exr::load_environment_map(imported.scene, base_dir, label);
    }
    if (!scene_has_light(imported.scene))
        cli::warning(label + ": the scene has no light (no sphere emits and there is no environment); it renders black");
    return std::move(imported.scene);
}

std::shared_ptr<const FrameSource> open_trajectory(const std::string& path, const cli::SceneReading& reading) {
    if (cli::is_stdio(path)) return nullptr;
    const bool series = is_series_pattern(path);  // "dump.*.lammpstrj": its files, one trajectory
    std::string_view format;
    if (!series) {
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) return nullptr;  // read_scene gives the error (or reads the FIFO)
        format = molecular_file_format(path);
        if (format.empty()) return nullptr;
    }
    // Checked before the trajectory is scanned.
    std::optional<Environment> environment = chosen_environment(reading, scene_folder(path), path);
    const MolecularImportOptions& options = reading.import.of<MolecularImportOptions>();
    std::unique_ptr<FrameSource> frames =
        series ? open_molecular_series(path, options) : open_molecular_file(path, format, options);
    if (environment) frames = std::make_unique<EnvironmentLitFrames>(std::move(frames), std::move(*environment));
    cli::warn_about_other_formats_options(reading, frames->format(), path);
    for (const std::string& message : frames->warnings()) cli::warning(message);
    return frames;
}

job::SceneInput read_scene_input(const std::string& path, const cli::SceneReading& reading) {
    job::SceneInput input;
    input.trajectory = open_trajectory(path, reading);
    if (input.trajectory) {
        input.label = path;
        input.imported = job::for_frame(1, [&] { return job::trajectory_frame(*input.trajectory, 1, input.label); });
    } else {
        input.imported = read_scene(path, input.label, reading);
    }
    return input;
}

}  // namespace orb::request
