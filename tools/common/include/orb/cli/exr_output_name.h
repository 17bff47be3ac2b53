// Tools that write OpenEXR only (orb-render, orb-merge) refuse an output
// named like another format: an EXR quietly written as out.png would fool
// every program that trusts the extension.
#pragma once

#include <string>

namespace orb::cli {

// Accepts "-", a name ending in .exr (any case) and a name without an
// extension (/dev/null, a FIFO); throws UsageError naming orb-tonemap otherwise.
void require_exr_output_name(const std::string& output);

}  // namespace orb::cli
