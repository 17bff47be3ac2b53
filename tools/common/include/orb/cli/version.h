// What `--version` prints for every Orb tool: the version (CMake's project
// VERSION), the source revision (read from git at each build) and the
// libraries the tools were built against, so a bug report or a farm node's
// log says exactly which build ran.
#pragma once

#include <string>

namespace orb::cli {

// "orb-render (Orb) 0.1.0", then "revision: ..." and "built with:" lines.
std::string version_text(const std::string& tool_name);

// The source revision alone: "git 3421385c1d2e", with "-dirty" for
// uncommitted changes, or why none is known (a tarball without git).
std::string source_revision();

}  // namespace orb::cli
