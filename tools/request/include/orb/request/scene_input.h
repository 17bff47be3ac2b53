// The scene as orb-render reads it (any format orb-import reads, its
// environment map loaded, import warnings printed). orb-frames --missing
// --scene reads it the same way, so both hash the same scene; the render
// job poses it (orb/job/scene_pose.h).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "orb/cli/scene_reading.h"
#include "orb/job/render_plan.h"
#include "orb/scene/error.h"
#include "orb/import/molecular.h"
#include "orb/scene/scene.h"

namespace orb::request {

// Reads and imports `path` ("-" for stdin) as `reading` asks (the
// importers' options, --environment); `label` becomes the path, or <stdin>.
// Throws orb::InputError for bad input, and for a scene without spheres
// unless reading.import.allow_empty (--allow-empty).
Scene read_scene(const std::string& path, std::string& label, const cli::SceneReading& reading);

// A molecular or particle file (PDB, mmCIF, XYZ, LAMMPS dump, .gro: its
// content or name says so) opened frame by frame: frame f of --frames is
// frame f of the file, counted from 1, read from the file when it is
// rendered. A numbered series ("dump.*.lammpstrj", orb/import/numbered_series.h)
// is one trajectory of its files' frames. Null for any other scene, and for
// stdin (read whole by read_scene, which takes its first frame). Every frame
// has the environment `reading` chooses. Prints the reader's warnings.
// Throws orb::InputError.
std::shared_ptr<const FrameSource> open_trajectory(const std::string& path, const cli::SceneReading& reading);

// The scene a render job poses, read as orb-render reads it (orb-frames
// --missing --scene reads it the same): a trajectory opened with its frame 1
// read (open_trajectory; its errors say "frame 1: "), else the whole scene
// (read_scene). Throws orb::InputError.
job::SceneInput read_scene_input(const std::string& path, const cli::SceneReading& reading);

}  // namespace orb::request
