// Scene.save: the canonical JSON scene or its binary form (.orb), written as
// orb-import writes its output (orb/cli/output_file.h: a previous file
// survives any failure).
#pragma once

#include <string>

#include "orb/scene/scene.h"

namespace orb::python {

// `path` ending in .orb: the binary form; .json: JSON; anything else raises
// ValueError. A relative environment map is rebased from the current
// directory to the file's folder.
void save_scene(const Scene& scene, const std::string& path);

}  // namespace orb::python
