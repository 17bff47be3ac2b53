#include "gltf_fuzz_check.h"

#include <stdexcept>

#include "orb/scene/animation.h"
#include "orb/scene/error.h"
#include "orb/import/gltf.h"
#include "orb/scene/scene_json.h"

namespace orb::fuzz {

void check_gltf_input(std::string_view bytes) {
    GltfImportResult result;
    try {
        result = import_gltf(bytes, "fuzz.gltf", "", {});
    } catch (const InputError&) {
        return;  // cleanly rejected
    }
    const Scene& scene = result.scene;
    if (load_scene_json(write_scene_json(scene), "fuzz.json") != scene)
        throw std::logic_error("imported scene does not survive the JSON round trip");
    const double start = scene.animation.start_time(), end = scene.animation.end_time();
    for (double t : {start - 1.0, start, 0.5 * (start + end), end, end + 1.0}) {
        const Scene at = scene_at_time(scene, t);
        if (at.spheres.size() != scene.spheres.size() || !at.animation.empty())
            throw std::logic_error("scene_at_time changed the sphere count or kept the animation");
    }
}

}  // namespace orb::fuzz
