// Environment maps from OpenEXR files (docs/scene-format.md, "Environment").
//
// Where the map's texels are loaded, and why here: the scene model (libscene)
// holds only the description ("map": a path, intensity, rotation) and, once
// loaded, the texels as plain floats (orb::EnvironmentImage); librender
// samples those floats and knows no image format; libexr is the one library
// that links OpenEXR. The front ends connect them: orb-render calls
// load_environment_map right after importing a scene, before hashing and
// rendering it. orb-import, which only converts scenes, never opens a map
// and does not link OpenEXR.
#pragma once

#include <string>

#include "orb/scene/scene.h"

namespace orb::exr {

// Reads an equirectangular (latitude-longitude) map: its R, G and B channels
// (or Y, as grey) over the data window, as 32-bit floats whatever they are
// stored as; row 0 is the top row. Throws orb::InputError naming `path` for
// a missing or unreadable file, one that is not an OpenEXR file, a deep or
// cube-map EXR, no colour channels, or more than kMaxEnvironmentTexels.
// The values are not checked here (see load_environment_map).
EnvironmentImage read_environment_exr(const std::string& path);

// For a scene whose environment is a map: resolves `map` (a relative path
// against `scene_dir`, the folder of the scene file; the current directory
// for a scene read from stdin), reads it, checks every texel (finite, >= 0,
// within the float limits once scaled by the intensity) and attaches the
// texels to scene.environment.image. Other scenes are left alone. Throws
// orb::InputError as "<source>: environment.map: <what is wrong>".
void load_environment_map(Scene& scene, const std::string& scene_dir, const std::string& source);

}  // namespace orb::exr
