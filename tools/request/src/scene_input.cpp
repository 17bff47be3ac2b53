#include "orb/request/scene_input.h"

#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/exr/camera_matrices.h"
#include "orb/exr/environment_map.h"
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

Scene trajectory_frame(const FrameSource& frames, long frame, const std::string& label) {
    require_trajectory_frames(frames, {frame}, label);
    Scene scene = frames.frame(static_cast<std::size_t>(frame - 1));
    validate_scene(scene, label);  // the caller names the frame (for_frame)
    return scene;
}

void require_trajectory_frames(const FrameSource& source, const std::vector<long>& frames, const std::string& label) {
    const std::size_t count = source.frame_count();
    for (long frame : frames)
        if (frame < 1 || static_cast<std::size_t>(frame) > count)
            throw InputError(label + ": has " + std::to_string(count) + (count == 1 ? " frame" : " frames") + " (1-" +
                             std::to_string(count) + "); there is no frame " + std::to_string(frame) +
                             " (frame 1 is the file's first)");
}

Scene pose_scene(const Scene& imported, double seconds, const std::string& label) {
    Scene posed = scene_at_time(imported, seconds);
    if (!imported.animation.empty()) {
        std::ostringstream at;
        at << label << " at " << seconds << " s";
        validate_scene(posed, at.str());
    }
    return posed;
}

Scene pose_scene(Scene&& imported, double seconds, const std::string& label) {
    if (imported.animation.empty()) return std::move(imported);
    return pose_scene(static_cast<const Scene&>(imported), seconds, label);
}

void apply_camera_request(Scene& posed, const RequestSettings& settings, std::optional<long> frame,
                          const std::string& label) {
    // The image's size: the command line's, else the scene's (orb-frames without --scene compares no camera).
    cli::apply_camera_options(settings.camera, posed, settings.width.value_or(posed.render.width),
                              settings.height.value_or(posed.render.height), label);
    if (settings.orbit && frame) posed.camera = settings.orbit->turn(posed.camera, *frame);
}

bool camera_moves(const RequestSettings& settings) { return settings.orbit.has_value(); }

exr::SceneIdentity scene_identity(const Scene& posed, const std::string& hash, int width, int height) {
    return {hash, exr::world_to_camera(posed.camera), exr::world_to_ndc(posed.camera, width, height)};
}

}  // namespace orb::request
