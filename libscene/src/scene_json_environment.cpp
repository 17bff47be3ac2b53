#include "scene_json_environment.h"

#include <cmath>

#include "float_limits.h"
#include "orb/scene/detail/json_text.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"

namespace orb::detail {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

const std::string kPath = "environment";

void check(bool ok, const std::string& source, const std::string& path, const std::string& message) {
    if (!ok) throw InputError(source + ": " + path + ": " + message);
}

std::string vec3_text(const Vec3& v) {
    std::string text("[");  // appended, not "[" + string: GCC 12 warns falsely (-Wrestrict) on that form
    text += format_number(v[0]);
    text += ", ";
    text += format_number(v[1]);
    text += ", ";
    text += format_number(v[2]);
    text += "]";
    return text;
}

bool radiance_in_range(double value) { return std::isfinite(value) && value >= 0 && value <= kMaxEmission; }

// The first texel that is not radiance the renderer can carry, as a message;
// "" when all are. Texels times the intensity stay within kMaxEmission for
// the same reason sphere emission does (docs/scene-format.md, "Limits").
std::string first_bad_texel(const EnvironmentImage& image, double intensity) {
    static const char* const kChannels[3] = {"R", "G", "B"};
    const double limit = intensity > 0 ? kMaxEmission / intensity : INFINITY;
    for (std::size_t i = 0; i < image.rgb.size(); ++i) {
        const float value = image.rgb[i];
        if (std::isfinite(value) && value >= 0.0f && value <= limit) continue;
        const std::size_t texel = i / 3;
        const std::string where = "texel (" + std::to_string(texel % std::size_t(image.width)) + ", " +
                                  std::to_string(texel / std::size_t(image.width)) + ") channel " + kChannels[i % 3];
        if (std::isnan(value)) return where + " is NaN; an environment map holds finite radiance >= 0";
        if (!std::isfinite(value)) return where + " is infinite; an environment map holds finite radiance >= 0";
        if (value < 0) return where + " is negative (" + format_number(value) + "); radiance is >= 0";
        return where + " is " + format_number(value) + ", times intensity " + format_number(intensity) +
               " above " + format_number(kMaxEmission) + " (the renderer computes in 32-bit floats)";
    }
    return "";
}

}  // namespace

Environment environment_from_json(const JsonReader& r, const json& value) {
    r.object(value, kPath);
    Environment environment;
    const bool has_color = value.contains("color"), has_map = value.contains("map");
    if (has_color == has_map)
        r.fail(kPath, has_color ? "has both \"color\" and \"map\"; give one (a uniform colour or an image)"
                                : "expected \"color\" (a uniform radiance) or \"map\" (an equirectangular EXR image)");
    if (has_color) {
        for (const char* key : {"intensity", "rotation_deg"})
            if (value.contains(key))
                r.fail(kPath + "." + key, "applies to a \"map\"; a uniform \"color\" is the radiance itself");
        r.only_keys(value, kPath, {"color"});
        environment.kind = EnvironmentKind::Color;
        environment.color = r.numbers<3>(value["color"], kPath + ".color");
        return environment;
    }
    r.only_keys(value, kPath, {"map", "intensity", "rotation_deg"});
    environment.kind = EnvironmentKind::Map;
    environment.map = r.string(value["map"], kPath + ".map");
    if (value.contains("intensity")) environment.intensity = r.number(value["intensity"], kPath + ".intensity");
    if (value.contains("rotation_deg"))
        environment.rotation_deg = r.number(value["rotation_deg"], kPath + ".rotation_deg");
    return environment;
}

ordered_json environment_to_json(const Environment& environment) {
    ordered_json section;
    switch (environment.kind) {
        case EnvironmentKind::None: return nullptr;
        case EnvironmentKind::Color:
            section["color"] = ordered_json::array({environment.color[0], environment.color[1], environment.color[2]});
            break;
        case EnvironmentKind::Map:
            section["map"] = environment.map;
            section["intensity"] = environment.intensity;
            section["rotation_deg"] = environment.rotation_deg;
            break;
    }
    return section;
}

void validate_environment(const Environment& environment, const std::string& source) {
    switch (environment.kind) {
        case EnvironmentKind::None: return;
        case EnvironmentKind::Color:
            for (double c : environment.color)
                check(radiance_in_range(c), source, kPath + ".color",
                      "each component must be finite, >= 0 and <= " + format_number(kMaxEmission) +
                          " (radiance; the renderer computes in 32-bit floats), got " + vec3_text(environment.color));
            return;
        case EnvironmentKind::Map: break;
    }
    check(!environment.map.empty(), source, kPath + ".map", "must name an EXR file, got \"\"");
    check(radiance_in_range(environment.intensity), source, kPath + ".intensity",
          "must be finite, >= 0 and <= " + format_number(kMaxEmission) + kFloatReason +
              format_number(environment.intensity));
    check(std::isfinite(environment.rotation_deg) && std::fabs(environment.rotation_deg) <= kMaxSceneMagnitude, source,
          kPath + ".rotation_deg", magnitude_rule() + kFloatReason + format_number(environment.rotation_deg));
    if (!environment.image) return;
    const EnvironmentImage& image = *environment.image;
    const std::string where = kPath + ".map";
    check(image.width >= 1 && image.height >= 1, source, where,
          "\"" + environment.map + "\" has no texels (" + std::to_string(image.width) + "x" +
              std::to_string(image.height) + ")");
    check(double(image.width) * double(image.height) <= double(kMaxEnvironmentTexels), source, where,
          "\"" + environment.map + "\" has " + std::to_string(image.width) + "x" + std::to_string(image.height) +
              " texels, more than the " + std::to_string(kMaxEnvironmentTexels) + " Orb accepts");
    check(image.rgb.size() == std::size_t(image.width) * std::size_t(image.height) * 3, source, where,
          "\"" + environment.map + "\": the texels do not fill " + std::to_string(image.width) + "x" +
              std::to_string(image.height) + " RGB");
    const std::string bad = first_bad_texel(image, environment.intensity);
    check(bad.empty(), source, where, "\"" + environment.map + "\": " + bad);
}

}  // namespace orb::detail
