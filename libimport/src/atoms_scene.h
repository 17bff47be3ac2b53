// Private: a frame of atoms (atom_frame.h) -> a scene that renders as is:
// one sphere per atom with one shared material and a colour each, the
// optional cell overlay, the automatic camera and the default lights. The
// camera, the lights and the size of atoms without a radius are those of the
// first frame, kept in a FrameView for every later frame: a trajectory's
// video then holds still. The numbers are documented in docs/orb-import.md.
#pragma once

#include <string>

#include "atom_frame.h"
#include "orb/import/molecular.h"

namespace orb::molecular {

struct FrameView {
    bool set = false;        // false until the first frame has fixed it
    Camera camera;
    Vec3 light_center{};
    double light_radius = 1;
    double default_radius = 1;  // atoms with neither an element nor a radius
    double cell_radius = 0;     // the cell overlay's spheres
};

// The sRGB colours atoms without an element are drawn in, by their type's
// index: the Okabe-Ito palette (M. Okabe, K. Ito, "Color Universal Design",
// 2008) without its black, then again.
Vec3 type_color(std::size_t type_index);

// Throws InputError naming `source` when the first frame has no atom, or lies
// too far from the origin for a camera to frame it.
Scene atoms_scene(AtomFrame frame, const MolecularImportOptions& options, FrameView& view, const std::string& source);

}  // namespace orb::molecular
