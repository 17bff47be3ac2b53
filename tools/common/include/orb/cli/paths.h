// Where an Orb tool finds its data: <dir of executable>/../share/orb, which is
// the layout of both the build tree and an installed tree.
#pragma once

#include <string>

namespace orb::cli {

std::string executable_path();
std::string share_dir();  // throws orb::InputError if nothing is found
std::string version_string();

}  // namespace orb::cli
