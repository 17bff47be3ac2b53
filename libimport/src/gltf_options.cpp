// The glTF importer's options (docs/gltf.md lists the rules they change).
#include <CLI/CLI.hpp>

#include <map>
#include <string>

#include "import_option_groups.h"
#include "orb/import/gltf.h"
#include "option_checks.h"

namespace orb::detail {
namespace {

constexpr const char* kGltfHeading = "glTF input";

void add_gltf_options(CLI::App& app, ImportOptions& import) {
    GltfImportOptions& options = import.of<GltfImportOptions>();
    const std::string group = kGltfHeading;
    // --gltf-scene, not --scene: orb-frames' --scene names the scene file.
    app.add_option("--gltf-scene", options.scene,
                   "glTF scene to import, by index or name (default: the asset's default scene)")
        ->option_text("N|NAME")
        ->group(group);
    app.add_option("--camera", options.camera,
                   "glTF camera to use, by camera index, camera name or node name (default: the first one found; "
                   "none: an automatic camera framing the scene from +z)")
        ->option_text("N|NAME")
        ->group(group);
    app.add_option("--animation", options.animation,
                   "glTF animation (clip) to import, by index or name (default: the first; the others are named in a "
                   "warning)")
        ->option_text("N|NAME")
        ->group(group);
    app.add_option("--sphere-tolerance", options.sphere_tolerance,
                   "A mesh is a sphere when all its vertices lie within this fraction of the radius of one sphere "
                   "(default 0.001)")
        ->check(finite_number_check([](double f) { return f >= 0 && f <= 1; }, "a fraction in [0, 1]"))
        ->capture_default_str()
        ->option_text("FRACTION")
        ->group(group);
    app.add_option("--point-radius", options.point_radius,
                   "Radius of POINTS without a _RADIUS attribute, in world units (default: 1% of the point cloud's "
                   "bounding-box diagonal)")
        ->check(finite_number_check([](double r) { return r > 0; }, "a radius > 0"))
        ->option_text("R")
        ->group(group);
    const std::map<std::string, NonSpherePolicy> policies{
        {"skip", NonSpherePolicy::Skip}, {"bound", NonSpherePolicy::Bound}, {"error", NonSpherePolicy::Error}};
    app.add_option("--non-spheres", options.non_spheres,
                   "Meshes that are not spheres: skip them (one warning), replace them by their bounding sphere, or "
                   "fail")
        ->transform(CLI::CheckedTransformer(policies, CLI::ignore_case))
        ->option_text("skip|bound|error")
        ->default_str("skip")
        ->group(group);
    app.add_option("--light-radius", options.light_radius,
                   "Radius of the emissive sphere for each point/spot light, in world units (default: 1% of the "
                   "scene's bounding-box diagonal)")
        ->check(finite_number_check([](double r) { return r > 0; }, "a radius > 0"))
        ->option_text("R")
        ->group(group);
    app.add_flag("--directional-lights", options.directional_lights,
                 "Turn directional lights into a distant, large emissive sphere giving the same illuminance "
                 "(default: leave them out with a warning)")
        ->group(group);
    const std::map<std::string, LightUnits> light_units{{"photometric", LightUnits::Photometric},
                                                        {"radiometric", LightUnits::Radiometric}};
    app.add_option("--light-units", options.light_units,
                   "KHR_lights_punctual intensities: photometric (cd and lux through 683 lm/W, as Blender does) or "
                   "radiometric (1 cd = 1 W/sr, 1 lux = 1 W/m^2)")
        ->transform(CLI::CheckedTransformer(light_units, CLI::ignore_case))
        ->option_text("photometric|radiometric")
        ->default_str("photometric")
        ->group(group);
    app.add_flag("--no-default-light{false}", options.default_light,
                 "Leave an asset without any light unlit (default: give it a grey environment and a key light, with "
                 "a warning)")
        ->group(group);
}

}  // namespace

const ImportOptionGroup kGltfOptions{kGltfHeading, add_gltf_options};

}  // namespace orb::detail
