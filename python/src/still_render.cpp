#include "still_render.h"

#include <charconv>
#include <stdexcept>

#include "errors.h"
#include "keyword_options.h"
#include "orb/cli/number_checks.h"
#include "orb/exr/environment_map.h"
#include "orb/exr/passes.h"
#include "orb/scene/error.h"

namespace py = pybind11;

namespace orb::python {

std::shared_ptr<RenderedLayers> with_layers(job::RenderedImage image) {
    auto rendered = std::make_shared<RenderedLayers>();
    py::gil_scoped_release released;
    rendered->image = std::move(image);
    rendered->layers = rendered->image.layers();
    return rendered;
}

namespace {

// A number as the command line would write it, exactly (shortest round trip).
std::string number_word(double value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::string(text, end);
}

// orb-render's checks of --time, --target-error and --noise-threshold, with
// its messages ("--time: expected a positive number of seconds, got '-1'").
void check_limits(std::optional<double> target_error, std::optional<double> noise_threshold,
                  std::optional<double> time_limit) {
    CLI::App app{"orb.Scene.render"};
    app.set_help_flag();
    double parsed = 0;
    const CLI::Validator positive = cli::finite_number_where([](double v) { return v > 0; }, "a number > 0");
    app.add_option("--noise-threshold", parsed)->check(positive)->group("Render");
    app.add_option("--target-error", parsed)->check(positive)->group("Render");
    app.add_option("--time", parsed)
        ->check(cli::finite_number_where([](double v) { return v > 0; }, "a positive number of seconds"))
        ->group("Render");
    KeywordOptions given;
    if (noise_threshold) given.push_back({"noise_threshold", number_word(*noise_threshold)});
    if (target_error) given.push_back({"target_error", number_word(*target_error)});
    if (time_limit) given.push_back({"time", number_word(*time_limit)});
    parse_keyword_options(app, given, "render");
}

}  // namespace

job::StillSettings still_settings(int width, int height, std::uint64_t spp, std::uint64_t seed,
                                  const std::string& device, const std::vector<std::string>& passes, bool denoise,
                                  std::optional<double> target_error, std::optional<double> noise_threshold,
                                  std::optional<double> time_limit) {
    check_limits(target_error, noise_threshold, time_limit);
    job::StillSettings settings;
    settings.width = width;
    settings.height = height;
    settings.spp = spp;
    settings.seed = seed;
    settings.device = device;
    std::string list;
    for (const std::string& pass : passes) list += (list.empty() ? "" : ",") + pass;
    try {
        settings.passes = exr::parse_passes(list);
    } catch (const std::invalid_argument& e) {  // orb-render's usage error (exit status 2)
        throw_value_error(e.what());
    } catch (const InputError& e) {
        throw_value_error(e.what());
    }
    settings.denoise = denoise;
    settings.target_error = target_error;
    settings.noise_threshold = noise_threshold;
    settings.time_limit = time_limit;
    return settings;
}

const Scene& scene_to_render(const Scene& posed, Scene& with_map) {
    if (posed.environment.kind != EnvironmentKind::Map || posed.environment.image) return posed;
    with_map = posed;
    exr::load_environment_map(with_map, ".", "scene");
    return with_map;
}

}  // namespace orb::python
