// orb.load: any scene Orb reads, through libimport's registry, shaped by the
// options orb-import takes (docs/orb-import.md) given as keywords.
#pragma once

#include <string>
#include <vector>

#include "keyword_options.h"
#include "orb/scene/scene.h"

namespace orb::python {

struct LoadedScene {
    Scene scene;
    std::vector<std::string> warnings;  // what orb-import would warn about, for Python's warnings
};

// Reads `path` as orb-import reads its INPUT with `options`; its environment
// map, if any, is named relative to the current directory (where Python
// resolves paths). With `text`, that is the input, `path` only its name in
// messages (the adapters hand over a frame they wrote). Throws as errors.h says.
LoadedScene load_scene(const std::string& path, const KeywordOptions& options, const std::string* text = nullptr);

// Applies orb-import's camera options (camera_position, look_at, up, vfov,
// aperture, focus_distance, orthographic, auto_camera) to `scene`.
void set_camera_options(Scene& scene, const KeywordOptions& options);

}  // namespace orb::python
