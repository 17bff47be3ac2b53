// Private: the text formats whose frames follow one another in one file
// (XYZ, LAMMPS dump, GROMACS .gro): each can skip a frame cheaply (for the
// scan that finds where frames start) and read one (for the frame asked for).
#pragma once

#include <string>
#include <string_view>

#include "atom_frame.h"
#include "line_reader.h"

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

const TextFormat& xyz_format();
const TextFormat& lammps_dump_format();
const TextFormat& gro_format();

}  // namespace orb::molecular
