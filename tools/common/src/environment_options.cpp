// The --environment options (docs/orb-import.md, "Environment").
#include "orb/cli/environment_options.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "orb/cli/map_paths.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"

namespace orb::cli {
namespace {

namespace fs = std::filesystem;

// "0.5" or "1,0.9,0.8" as numbers; nothing when any part is not a number
// (then the value is a path).
std::optional<std::vector<double>> numbers_of(const std::string& text) {
    std::vector<double> values;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        double value = 0;
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
        if (part.empty() || error != std::errc() || end != part.data() + part.size()) return std::nullopt;
        values.push_back(value);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return values;
}

bool radiance_in_range(double value) { return std::isfinite(value) && value >= 0 && value <= kMaxEmission; }

// OpenEXR files start with the magic number 20000630 (little-endian).
bool is_openexr(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    return in.gcount() == 4 && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

}  // namespace

void add_environment_options(CLI::App& app, EnvironmentChoice& choice) {
    app.add_option("--environment", choice.value,
                   "Light the scene from infinitely far away: R,G,B (or V) is a uniform radiance, anything else the "
                   "path of an equirectangular OpenEXR map; replaces the scene's own environment (and a glTF asset's "
                   "default light)")
        ->option_text("R,G,B|MAP.exr")
        ->group("Environment");
    app.add_option("--environment-intensity", choice.intensity,
                   "Multiplies the environment's radiance (default 1)")
        ->option_text("S")
        ->group("Environment");
    app.add_option("--environment-rotation", choice.rotation_deg,
                   "Turns the map about +y, in degrees, right-handed (default 0)")
        ->option_text("DEG")
        ->group("Environment");
}

std::optional<Environment> chosen_environment(const EnvironmentChoice& choice, const std::string& scene_dir) {
    if (choice.value.empty()) return std::nullopt;
    const std::string what = "--environment " + choice.value;
    if (!radiance_in_range(choice.intensity))
        throw InputError("--environment-intensity: must be finite, >= 0 and <= 1e12");
    if (!std::isfinite(choice.rotation_deg) || std::fabs(choice.rotation_deg) > kMaxSceneMagnitude)
        throw InputError("--environment-rotation: must be a finite angle in degrees");
    Environment environment;
    if (const auto values = numbers_of(choice.value)) {
        if (values->size() != 1 && values->size() != 3)
            throw InputError(what + ": a colour is one value or three (R,G,B), got " +
                             std::to_string(values->size()));
        environment.kind = EnvironmentKind::Color;
        for (int c = 0; c < 3; ++c) {
            const double radiance = (*values)[values->size() == 1 ? 0 : c] * choice.intensity;
            if (!radiance_in_range(radiance))
                throw InputError(what + ": radiance must be finite, >= 0 and <= 1e12 (times the intensity)");
            environment.color[c] = radiance;
        }
        return environment;
    }
    const fs::path map(choice.value);
    if (!fs::is_regular_file(map)) throw InputError(what + ": no such file");
    if (!is_openexr(map))
        throw InputError(what + ": not an OpenEXR file (Orb reads environment maps as EXR; convert one with, for "
                                "example, oiiotool sky.hdr -o sky.exr)");
    environment.kind = EnvironmentKind::Map;
    environment.map = rebased_map_path(choice.value, fs::current_path().string(), scene_dir);
    environment.intensity = choice.intensity;
    environment.rotation_deg = choice.rotation_deg;
    return environment;
}

}  // namespace orb::cli
