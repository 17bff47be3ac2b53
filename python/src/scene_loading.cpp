#include "scene_loading.h"

#include <filesystem>
#include <optional>

#include "errors.h"
#include "orb/cli/camera_options.h"
#include "orb/cli/io.h"
#include "orb/cli/map_paths.h"
#include "orb/cli/messages.h"
#include "orb/cli/scene_reading.h"
#include "orb/cli/sphere_style_options.h"
#include "orb/cli/texture_decoder_loader.h"
#include "orb/import/gltf.h"
#include "orb/import/importers.h"
#include "orb/import/molecular.h"
#include "orb/import/numbered_series.h"
#include "orb/scene/error.h"
#include "package_folder.h"

namespace orb::python {
namespace {

// What orb-import's command line holds, less what only a tool has (its
// output, --to, --list-formats, --legend).
struct LoadArguments {
    std::string from;
    bool strict = false;
    cli::SceneReading reading;
    cli::CameraOptions camera;
    cli::SphereStyleArguments style;
};

void add_load_options(CLI::App& app, LoadArguments& args) {
    app.set_help_flag();
    app.add_option("--from", args.from)->check(CLI::IsMember(scene_format_words()))->group("Input");
    app.add_flag("--strict", args.strict)->group("Input");
    app.add_flag("--allow-empty", args.reading.import.allow_empty)->group("Input");
    cli::add_scene_reading_options(app, args.reading);
    const std::string_view molecules = find_scene_importer("xyz")->options->heading;
    args.reading.importer_options.push_back(
        {app.add_option("--frame", args.reading.import.of<MolecularImportOptions>().frame)
             ->check(CLI::PositiveNumber)
             ->group(std::string(molecules)),
         molecules});
    cli::add_camera_options(app, args.camera);
    cli::add_sphere_style_options(app, args.style);
    app.remove_option(app.get_option("--legend"));  // a file beside an output: orb-import's
    app.remove_option(app.get_option("--legend-layout"));
}

std::string folder_of(const std::string& path) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

// The input's bytes; a file that is not there is FileNotFoundError.
std::string read_file(const std::string& path) {
    try {
        return cli::read_input(path);
    } catch (const InputError& e) {
        std::error_code ignored;
        if (!std::filesystem::exists(path, ignored)) throw_file_not_found(e.what());
        throw;
    }
}

}  // namespace

LoadedScene load_scene(const std::string& path, const KeywordOptions& options, const std::string* text) {
    CLI::App app{"orb.load"};
    LoadArguments args;
    add_load_options(app, args);
    parse_keyword_options(app, options, "load");
    if (!text && path == "-") throw_value_error("load: reading stdin is orb-import's; give a file's path");

    const SphereStyleOptions style = cli::sphere_style_options(args.style);
    ImportOptions import_options = cli::import_options_for(args.reading);
    import_options.format = args.from;
    import_options.of<GltfImportOptions>().strict = args.strict;
    // The tools' run-time module, from the package's own lib folder (not
    // linked: the module must import where OpenImageIO is not installed).
    import_options.of<GltfImportOptions>().image_decoder = cli::texture_decoder_in(runtime_module_folder());
    // Python resolves paths from the current directory.
    std::optional<Environment> environment = cli::chosen_environment(args.reading.environment, ".");

    LoadedScene loaded;
    ImportResult imported = text                      ? import_scene(*text, path, ".", import_options)
                            : is_series_pattern(path) ? import_molecular_series(path, import_options)
                                                      : import_scene(read_file(path), path, folder_of(path), import_options);
    if (args.strict && !imported.warnings.empty()) {
        std::string message = path + " would lose information (strict=True):";
        for (const std::string& loss : imported.warnings) message += "\n  " + loss;
        throw InputError(message);
    }
    loaded.warnings = std::move(imported.warnings);
    loaded.warnings.insert(loaded.warnings.end(), imported.notices.begin(), imported.notices.end());
    // Its warning goes to Python's warnings with the importer's.
    cli::set_warning_sink([&loaded](const std::string& message) { loaded.warnings.push_back(message); });
    cli::warn_about_other_formats_options(args.reading, imported.format, path);
    cli::set_warning_sink({});
    cli::rebase_environment_map(imported.scene, folder_of(path), ".");
    if (environment) imported.scene.environment = std::move(*environment);
    cli::apply_sphere_style(imported.scene, style, path);
    cli::apply_camera_options(args.camera, imported.scene, imported.scene.render.width,
                              imported.scene.render.height, path);
    loaded.scene = std::move(imported.scene);
    return loaded;
}

void set_camera_options(Scene& scene, const KeywordOptions& options) {
    CLI::App app{"orb.Scene.set_camera"};
    app.set_help_flag();
    cli::CameraOptions camera;
    cli::add_camera_options(app, camera);
    parse_keyword_options(app, options, "set_camera");
    // A change refused leaves the scene as it was (the options change its camera alone).
    const Camera before = scene.camera;
    try {
        cli::apply_camera_options(camera, scene, scene.render.width, scene.render.height, "set_camera");
    } catch (...) {
        scene.camera = before;
        throw;
    }
}

}  // namespace orb::python
