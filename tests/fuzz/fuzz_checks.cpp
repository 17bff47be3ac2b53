#include "fuzz_checks.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "orb/scene/error.h"
#include "orb/import/molecular.h"
#include "orb/import/ply.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"
#include "orb/import/scn.h"

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

namespace {

void check_attributes(const Scene& scene) {
    const std::size_t spheres = scene.spheres.size();
    const SphereAttributes& attributes = scene.sphere_attributes;
    if (attributes.colors.size() != 3 * spheres) throw std::logic_error("molecular frame: not one colour per sphere");
    for (float c : attributes.colors)
        if (!(c >= 0 && c <= 1)) throw std::logic_error("molecular frame: a colour outside [0, 1]");
    for (const SphereProperty& property : attributes.properties) {
        if (property.values.size() != spheres)
            throw std::logic_error("molecular frame: property " + property.name + " has not one value per sphere");
        for (float v : property.values) {
            if (!has_value(v)) continue;  // a sphere that is not an atom (the cell, a light) has no value
            if (!std::isfinite(v)) throw std::logic_error("molecular frame: property " + property.name + " not finite");
            if (property.categorical() && !(v >= 0 && v < property.labels.size() && v == std::floor(v)))
                throw std::logic_error("molecular frame: property " + property.name + " indexes no label");
        }
    }
}

}  // namespace

void check_molecular_input(std::string_view bytes) {
    constexpr std::size_t kMaxFramesChecked = 8;
    for (std::string_view format : {"pdb", "mmcif", "xyz", "lammps-dump", "gro"}) {
        try {
            const auto frames = open_molecular_bytes(bytes, "fuzz", format, {.cell = true});
            if (frames->frame_count() == 0) throw std::logic_error("a frame source without frames");
            std::optional<Camera> first_camera;
            for (std::size_t k = 0; k < std::min(frames->frame_count(), kMaxFramesChecked); ++k) {
                const Scene scene = frames->frame(k);
                validate_scene(scene, "fuzz");
                check_attributes(scene);
                if (first_camera && scene.camera != *first_camera)
                    throw std::logic_error("a later frame's camera differs from the first frame's");
                first_camera = scene.camera;
            }
        } catch (const InputError&) {
        }
    }
}

}  // namespace orb::fuzz
