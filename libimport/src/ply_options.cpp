// The PLY importer's options (docs/orb-import.md, "PLY point clouds").
#include <CLI/CLI.hpp>

#include "import_option_groups.h"
#include "orb/import/ply.h"
#include "option_checks.h"

namespace orb::detail {
namespace {

constexpr const char* kPlyHeading = "PLY input";

void add_ply_options(CLI::App& app, ImportOptions& options) {
    app.add_option("--radius", options.of<PlyImportOptions>().radius,
                   "Radius of PLY points without a radius property, in scene units (default: half the typical "
                   "spacing, bounding-box diagonal / (2*sqrt(3)*cbrt(points)), stray points left out)")
        ->check(finite_number_check([](double r) { return r > 0; }, "a radius > 0"))
        ->option_text("R")
        ->group(kPlyHeading);
}

}  // namespace

const ImportOptionGroup kPlyOptions{kPlyHeading, add_ply_options};

}  // namespace orb::detail
