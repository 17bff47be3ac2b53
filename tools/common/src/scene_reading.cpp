#include "orb/cli/scene_reading.h"

#include "orb/cli/messages.h"
#include "orb/cli/texture_decoder_loader.h"
#include "orb/import/gltf.h"
#include "orb/import/importers.h"

namespace orb::cli {

void add_scene_reading_options(CLI::App& app, SceneReading& reading) {
    for (const ImportOptionGroup* group : import_option_groups()) {
        const std::size_t before = app.get_options().size();
        group->add(app, reading.import);
        const std::vector<CLI::Option*> options = app.get_options();
        for (std::size_t i = before; i < options.size(); ++i)
            reading.importer_options.push_back({options[i], group->heading});
    }
    add_environment_options(app, reading.environment);
}

bool any_scene_reading_option(const SceneReading& reading) {
    for (const SceneReading::ImporterOption& given : reading.importer_options)
        if (given.option->count() > 0) return true;
    return !reading.environment.value.empty();
}

ImportOptions import_options_for(const SceneReading& reading) {
    ImportOptions options = reading.import;
    if (!reading.environment.value.empty()) options.of<GltfImportOptions>().default_light = false;  // the chosen environment lights it
    options.of<GltfImportOptions>().image_decoder = texture_decoder();
    return options;
}

void warn_about_other_formats_options(const SceneReading& reading, std::string_view format, const std::string& source) {
    const SceneImporter* reader = find_scene_importer(format);
    const std::string_view own = reader && reader->options ? reader->options->heading : std::string_view();
    std::string given;
    for (const SceneReading::ImporterOption& option : reading.importer_options) {
        if (option.heading == own || option.option->count() == 0) continue;
        if (!given.empty()) given += ", ";
        given += option.option->get_name() + " (" + std::string(option.heading) + ")";
    }
    if (!given.empty())
        warning(source + ": ignored " + given + ": the input is read as " + std::string(format) +
                " (orb-import --list-formats says which options each format takes)");
}

}  // namespace orb::cli
