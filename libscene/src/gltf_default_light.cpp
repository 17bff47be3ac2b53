// An asset with no light at all would render black (many sample assets
// rely on the viewer's lighting): it gets a neutral uniform environment,
// as a glTF viewer gives one (docs/gltf.md, "Default light").
#include "gltf_internal.h"
#include "json_text.h"

namespace orb::gltf {

void add_default_light(Scene& scene, const std::string& source, std::vector<std::string>& notices) {
    if (scene_has_light(scene)) return;
    const double l = kDefaultEnvironmentRadiance;
    scene.environment = Environment{};
    scene.environment.kind = EnvironmentKind::Color;
    scene.environment.color = {l, l, l};
    notices.push_back(source +
                      ": the asset has no light (no KHR_lights_punctual light imported, no emissive material); added a "
                      "uniform white environment of radiance " + detail::format_number(l) +
                      " (--no-default-light leaves the scene unlit)");
}

}  // namespace orb::gltf
