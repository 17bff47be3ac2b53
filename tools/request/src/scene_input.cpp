#include "orb/request/scene_input.h"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/exr/camera_matrices.h"
#include "orb/exr/environment_map.h"
#include "orb/cli/texture_decoder_loader.h"
#include "orb/scene/animation.h"
#include "orb/scene/import.h"
#include "orb/scene/importers.h"
#include "orb/scene/error.h"
#include "orb/scene/numbered_series.h"
#include "orb/scene/scene_json.h"

namespace orb::request {

namespace fs = std::filesystem;

Scene read_scene(const std::string& path, std::string& label, bool allow_empty, const MolecularImportOptions& molecule) {
    label = cli::is_stdio(path) ? "<stdin>" : path;
    const std::string bytes = cli::read_input(path);
    const std::string base_dir =
        cli::is_stdio(path) ? fs::current_path().string() : fs::absolute(path).parent_path().string();
    ImportOptions options;
    options.allow_empty = allow_empty;
    options.molecular = molecule;
    options.gltf.image_decoder = cli::texture_decoder();  // glTF textures, through OpenImageIO, loaded when needed
    ImportResult imported = import_scene(bytes, label, base_dir, options);
    for (const std::string& message : imported.warnings) cli::warning(message);
    for (const std::string& message : imported.notices) cli::warning(message);
    // The map's texels join the scene before it is hashed (they are part of its identity) and rendered.
    exr::load_environment_map(imported.scene, base_dir, label);
    if (!scene_has_light(imported.scene))
        cli::warning(label + ": the scene has no light (no sphere emits and there is no environment); it renders black");
    return std::move(imported.scene);
}

std::shared_ptr<const FrameSource> open_trajectory(const std::string& path, const MolecularImportOptions& options) {
    if (cli::is_stdio(path)) return nullptr;
    std::shared_ptr<const FrameSource> frames;
    if (is_series_pattern(path)) {
        frames = open_molecular_series(path, options);  // "dump.*.lammpstrj": its files, one trajectory
    } else {
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) return nullptr;  // read_scene gives the error (or reads the FIFO)
        const std::string_view format = molecular_file_format(path);
        if (format.empty()) return nullptr;
        frames = open_molecular_file(path, format, options);
    }
    for (const std::string& message : frames->warnings()) cli::warning(message);
    return frames;
}

Scene trajectory_frame(const FrameSource& frames, long frame, const std::string& label) {
    require_trajectory_frames(frames, {frame}, label);
    Scene scene = frames.frame(static_cast<std::size_t>(frame - 1));
    validate_scene(scene, label + " frame " + std::to_string(frame));
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
