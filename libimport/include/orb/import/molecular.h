// Molecular and particle files (PDB, mmCIF, XYZ and extended XYZ, LAMMPS
// dumps, GROMACS .gro) -> scenes of spheres, one per atom: coloured by
// element (Scene::sphere_attributes.colors, one shared material), sized by
// the element table (orb/import/elements.h), the file's per-atom columns kept
// as properties. Every rule is in docs/orb-import.md ("Molecules and particles").
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "orb/scene/scene.h"

namespace orb {

enum class AtomRadius {
    VanDerWaals,  // the element's van der Waals radius (default)
    Covalent,     // the element's covalent radius
    Fixed,        // MolecularImportOptions::fixed_radius for every atom
};

struct MolecularImportOptions {
    AtomRadius radius = AtomRadius::VanDerWaals;
    double fixed_radius = 0.0;  // with Fixed: > 0, in the file's length unit (angstrom; .gro's nm become angstrom)
    double radius_scale = 1.0;  // every radius from the element table times this (> 0): 0.25 for ball-and-stick-like atoms
    bool cell = false;          // draw the simulation cell's 12 edges as rows of small spheres
    bool drop_hydrogens = false;  // PDB/mmCIF: leave out H (and D) atoms
    bool all_altlocs = false;     // PDB/mmCIF: keep every alternate location, not only the first/most occupied
    // Which frame orb-import writes (1 = the file's first frame; a still
    // render takes frame 1). orb-render --frames reads them all.
    long frame = 1;
    bool operator==(const MolecularImportOptions&) const = default;
};

// A file of one or more frames (a trajectory, the models of an NMR
// ensemble), read one frame at a time. Text trajectories keep only the byte
// offset of each frame (found by one cheap scan) and read a frame's bytes
// when it is asked for, so a trajectory of a million atoms in a thousand
// frames renders with the memory of a frame or two. The camera and the
// default lights are those of frame 1 in every frame, so a video holds still.
class FrameSource {
public:
    virtual ~FrameSource() = default;
    virtual std::size_t frame_count() const = 0;
    // Frame `index` (0-based) as a scene; throws InputError naming the file,
    // the line and what was expected. Safe to call from one thread at a time
    // while another thread uses the scenes it returned.
    virtual Scene frame(std::size_t index) const = 0;
    // What reading lost (unknown element names, ...), from the scan and frame 1.
    virtual const std::vector<std::string>& warnings() const = 0;
    virtual std::string_view format() const = 0;  // the importer's name: "lammps-dump"
    // How many frame scenes the source has built so far, frame 1's for the
    // camera included: what reading a trajectory cost (tests check that
    // frame 1 is read once).
    virtual std::size_t frames_built() const = 0;
};

// The molecular importer a file's first bytes (or, for .gro whose content
// has no signature, its name) show; empty when the file is none of them.
// `head` is the start of the file (a few kilobytes are enough).
std::string_view recognise_molecular_file(std::string_view head, const std::string& path);

// Opens `path` (a file, read frame by frame) as the named molecular format.
// Throws InputError for a file that cannot be read or whose frames are malformed.
std::unique_ptr<FrameSource> open_molecular_file(const std::string& path, std::string_view format,
                                                 const MolecularImportOptions& options);

// The molecular format of the file at `path`, as orb-render tells it: its
// first bytes, else its name (.gro), unless its content is another
// importer's; empty when it is none. Throws InputError when it cannot be read.
std::string_view molecular_file_format(const std::string& path);

// A numbered series (orb/import/numbered_series.h: "dump.*.lammpstrj") as one
// trajectory: the frames of its files in the order of their numbers, each
// file's frames one after another, every file scanned once for where its
// frames start and read when a frame is asked for. Every file must be of one
// text trajectory format (XYZ, LAMMPS dump, .gro). Throws InputError for the
// series' errors, a file of another format than the first (naming both), a
// PDB or mmCIF series, and a malformed file.
std::unique_ptr<FrameSource> open_molecular_series(const std::string& pattern, const MolecularImportOptions& options);

// The same over bytes already in memory (stdin, orb-import); `bytes` must outlive the source.
std::unique_ptr<FrameSource> open_molecular_bytes(std::string_view bytes, const std::string& source,
                                                  std::string_view format, const MolecularImportOptions& options);

}  // namespace orb
