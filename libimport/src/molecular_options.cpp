// The molecular and particle importers' options (docs/orb-import.md,
// "Molecules and particles"): PDB, mmCIF, XYZ, LAMMPS dumps and .gro read
// with the same ones.
#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <string>

#include "import_option_groups.h"
#include "orb/import/molecular.h"

namespace orb::detail {
namespace {

constexpr const char* kMolecularHeading = "Molecule input";

void add_molecular_options(CLI::App& app, ImportOptions& import) {
    MolecularImportOptions& options = import.of<MolecularImportOptions>();
    const char* group = kMolecularHeading;
    app.add_option_function<std::string>(
           "--atom-radius",
           [&options](const std::string& value) {
               if (value == "vdw") {
                   options.radius = AtomRadius::VanDerWaals;
                   return;
               }
               if (value == "covalent") {
                   options.radius = AtomRadius::Covalent;
                   return;
               }
               double radius = 0;
               const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), radius);
               if (ec != std::errc() || end != value.data() + value.size() || !(radius > 0) || !std::isfinite(radius))
                   throw CLI::ValidationError("--atom-radius", "expected vdw, covalent or a radius > 0, got '" + value + "'");
               options.radius = AtomRadius::Fixed;
               options.fixed_radius = radius;
           },
           "Atom radius: vdw (van der Waals, the default), covalent, or one radius R for every atom "
           "(angstrom; the element table: docs/orb-import.md)")
        ->option_text("vdw|covalent|R")
        ->group(group);
    app.add_flag("--cell", options.cell,
                  "Draw the simulation cell (LAMMPS box, extended XYZ Lattice, .gro box, PDB CRYST1) as rows of "
                  "small spheres along its 12 edges")
        ->group(group);
    app.add_flag("--no-hydrogens", options.drop_hydrogens, "PDB/mmCIF: leave out hydrogen atoms")->group(group);
    app.add_flag("--all-altlocs", options.all_altlocs,
                 "PDB/mmCIF: keep every alternate location (default: per residue the most occupied, the first on a tie)")
        ->group(group);
}

}  // namespace

const ImportOptionGroup kMolecularOptions{kMolecularHeading, add_molecular_options};

}  // namespace orb::detail
