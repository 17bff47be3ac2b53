// Private: the text formats whose frames follow one another in one file
// (XYZ, LAMMPS dump, GROMACS .gro): each can skip a frame cheaply (for the
// scan that finds where frames start) and read one (for the frame asked for).
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "atom_frame.h"
#include "import_option_groups.h"
#include "line_reader.h"
#include "orb/import/importers.h"
#include "orb/import/molecular.h"

namespace orb::molecular {

struct TextFormat {
    std::string_view name;  // the importer's name
    // Reads past one frame from the reader's position, checking only what
    // tells where it ends (counts, section headers). False when nothing but
    // blank lines is left. Throws InputError naming the line.
    bool (*skip_frame)(LineReader& lines, const std::string& source);
    // Reads one frame from the reader's position. Throws InputError naming the line.
    AtomFrame (*read_frame)(LineReader& lines, const std::string& source);
};

// The frames of a text trajectory: one input, or a numbered series' files
// one after another (molecular_sources.cpp). Each format's importer entry
// (xyz_read.cpp, lammps_dump_read.cpp, gro_read.cpp) opens its files with it.
std::unique_ptr<FrameSource> open_text_trajectory(const TextFormat& format, const FrameInput& input,
                                                  const MolecularImportOptions& options);

template <const TextFormat& Format>
std::unique_ptr<FrameSource> open_text_frames(const FrameInput& input, const MolecularImportOptions& options) {
    return open_text_trajectory(Format, input, options);
}

// A text trajectory format's importer entry: `entry` (its names, its
// recognising) read frame by frame through Format, a numbered series of its
// files one trajectory, with the molecular options.
template <const TextFormat& Format>
SceneImporter text_trajectory_importer(SceneImporter entry) {
    entry.open_frames = open_text_frames<Format>;
    entry.reads_series = true;
    entry.options = &detail::kMolecularOptions;
    return entry;
}

}  // namespace orb::molecular
