// Recognising a scene file by content and importing it into the canonical model.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "orb/scene/gltf.h"
#include "orb/scene/ply.h"
#include "orb/scene/scene.h"

namespace orb {

enum class SceneFormat { Unknown, OrbJson, Scn, GltfJson, Glb, Ply, OrbBinary };

SceneFormat detect_scene_format(std::string_view bytes);
// The format a file name's extension promises: .gltf, .glb, .ply, .orb; Unknown for any other.
SceneFormat scene_format_from_extension(const std::string& path);
SceneFormat scene_format_from_name(const std::string& name);  // "orb","json","scn","gltf","glb","ply","orb-binary"
const char* scene_format_name(SceneFormat format);

struct ImportOptions {
    SceneFormat format = SceneFormat::Unknown;  // Unknown: detect by content (and the name's extension)
    // A scene without spheres is refused, with what was left out and why
    // (an asset of triangle meshes); true accepts it.
    bool allow_empty = false;
    GltfImportOptions gltf;
    PlyImportOptions ply;
};

struct ImportResult {
    Scene scene;
    std::vector<std::string> warnings;  // losses: an error for tools run with --strict
    std::vector<std::string> notices;   // additions, such as glTF's default light: warned about, never fatal
};

// `source` names the input in messages (a path, or <stdin>); without a chosen
// format its extension helps to choose one: a .gltf/.glb/.ply/.orb name goes
// to that reader even when the content is too broken to recognise, and a
// format Orb does not read (tri.obj, by content or by name) is refused as
// such. `base_dir` resolves external files (glTF buffers). Throws InputError.
ImportResult import_scene(std::string_view bytes, const std::string& source, const std::string& base_dir,
                          const ImportOptions& options = {});

}  // namespace orb
