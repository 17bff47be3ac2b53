#include "orb/image/color_options.h"

#include <cstdlib>

#include "orb/cli/paths.h"
#include "orb/scene/error.h"

namespace orb::image {

void add_color_options(CLI::App& app, ColorOptions& o) {
    app.add_option("--config", o.config_path, "OpenColorIO config (default: $OCIO, else Orb's own)")
        ->option_text("FILE");
    app.add_option("--display", o.display, "OCIO display (default: the config's default)")->option_text("NAME");
    app.add_option("--view", o.view, "OCIO view of that display (default: the display's default)")
        ->option_text("NAME");
    app.add_option("--look", o.look, "OCIO look(s) to apply, overriding the view's own")->option_text("NAME");
    app.add_option("--input-space", o.input_space,
                   "Colour space of the input's colour passes (default: scene_linear; sRGB for 8/16-bit files)")
        ->option_text("NAME");
    app.add_flag("--list", o.list, "Print the config's displays, views, looks and colour spaces, then exit");
}

ColorConfig load_color_config(const ColorOptions& o) {
    std::string default_path;
    const char* env = std::getenv("OCIO");
    if (o.config_path.empty() && !(env && *env)) default_path = orb::cli::share_dir() + "/ocio/config.ocio";
    return ColorConfig::load(o.config_path, default_path);
}

std::string input_space_for(const ColorConfig& config, const ColorOptions& o, const LoadedImage& image) {
    if (!o.input_space.empty()) {
        const std::string resolved = config.resolve_color_space(o.input_space);
        if (resolved.empty())
            throw InputError("unknown colour space '" + o.input_space + "' in " + config.source() +
                             " (see --list)");
        return resolved;
    }
    if (image.display_referred) return config.encoded_input_space(image.color_space);
    return config.scene_linear();
}

}  // namespace orb::image
