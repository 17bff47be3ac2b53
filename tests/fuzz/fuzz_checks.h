// What every fuzz input must satisfy, shared by the libFuzzer targets and by
// the unit test that replays tests/fuzz/corpus/ in ordinary builds (so a crash
// once found stays fixed without needing clang or libFuzzer).
//
// Each check returns normally when the input is accepted or cleanly rejected
// (orb::InputError); it throws std::logic_error when a property is broken,
// and anything else (a crash, another exception type) is a bug by itself.
#pragma once

#include <string_view>

namespace orb::fuzz {

// parse_scn either rejects the text or returns a scene that writes back to
// .scn and re-reads to the very same scene.
void check_scn_input(std::string_view bytes);

// load_scene_json either rejects the text or returns a scene with
// load(write(scene)) == scene.
void check_scene_json_input(std::string_view bytes);

// import_ply either rejects the bytes or returns a valid scene with
// load(write(scene)) == scene in Orb JSON, and says why exactly when it has
// no sphere.
void check_ply_input(std::string_view bytes);

// load_scene_binary either rejects the bytes or returns a scene that writes
// back to the same scene through both the binary and the JSON form.
void check_scene_binary_input(std::string_view bytes);

// Each molecular reader (PDB, mmCIF, XYZ, LAMMPS dump, .gro) either rejects
// the bytes or gives frames that are valid scenes whose per-sphere colours
// and properties have one entry per sphere (categorical ones indexing their
// labels), every camera the first frame's.
void check_molecular_input(std::string_view bytes);

}  // namespace orb::fuzz
