#include "fuzz_checks.h"

#include <stdexcept>
#include <string>

#include "orb/scene/error.h"
#include "orb/scene/ply.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"
#include "orb/scene/scn.h"

namespace orb::fuzz {

void check_scn_input(std::string_view bytes) {
    Scene scene;
    try {
        scene = parse_scn(bytes, "fuzz.scn");
    } catch (const InputError&) {
        return;  // a clean rejection
    }
    const ScnWriteResult written = write_scn(scene);
    if (!written.lossy.empty()) throw std::logic_error("a scene read from .scn is lossy in .scn: " + written.lossy.front());
    if (parse_scn(written.text, "rewritten.scn") != scene)
        throw std::logic_error("parse_scn(write_scn(scene)) != scene for:\n" + written.text);
    if (load_scene_json(write_scene_json(scene), "rewritten.json") != scene)
        throw std::logic_error("a scene read from .scn does not survive Orb JSON");
}

void check_scene_json_input(std::string_view bytes) {
    Scene scene;
    try {
        scene = load_scene_json(bytes, "fuzz.json");
    } catch (const InputError&) {
        return;
    }
    const std::string text = write_scene_json(scene);
    if (load_scene_json(text, "rewritten.json") != scene)
        throw std::logic_error("load_scene_json(write_scene_json(scene)) != scene for:\n" + text);
}

void check_ply_input(std::string_view bytes) {
    Scene scene;
    try {
        PlyImportResult result = import_ply(bytes, "fuzz.ply");
        // A scene without spheres always says why (import_scene refuses it with that reason).
        if (result.scene.spheres.empty() == result.no_spheres.empty())
            throw std::logic_error("import_ply: no_spheres must be set exactly when the scene has no sphere");
        scene = std::move(result.scene);
    } catch (const InputError&) {
        return;
    }
    validate_scene(scene, "fuzz.ply");
    if (load_scene_json(write_scene_json(scene), "rewritten.json") != scene)
        throw std::logic_error("a scene read from PLY does not survive Orb JSON");
}

void check_scene_binary_input(std::string_view bytes) {
    Scene scene;
    try {
        scene = load_scene_binary(bytes, "fuzz.orb");
    } catch (const InputError&) {
        return;
    }
    if (load_scene_binary(write_scene_binary(scene), "rewritten.orb") != scene)
        throw std::logic_error("load_scene_binary(write_scene_binary(scene)) != scene");
    if (load_scene_json(write_scene_json(scene), "rewritten.json") != scene)
        throw std::logic_error("a binary scene does not survive Orb JSON");
}

}  // namespace orb::fuzz
