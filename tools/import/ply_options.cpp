// orb-import's PLY options (docs/orb-import.md lists the rules they change).
#include "ply_options.h"

namespace orb::import_tool {

void add_ply_options(CLI::App& app, PlyImportOptions& options) {
    app.add_option("--radius", options.radius,
                   "Radius of PLY points without a radius property, in scene units (default: half the typical "
                   "spacing, bounding-box diagonal / (2*sqrt(3)*cbrt(points)), stray points left out)")
        ->check(CLI::PositiveNumber)
        ->option_text("R")
        ->group("PLY input");
}

}  // namespace orb::import_tool
