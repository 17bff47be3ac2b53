// Where the package orb lies on disk, found from the extension module itself:
// the files the package carries beside orb._orb (its run-time modules) are
// found there wherever the package was installed or copied.
#pragma once

#include <string>

namespace orb::python {

// The folder holding orb._orb (…/orb).
std::string package_folder();

// The package's folder of run-time modules (…/orb/lib): the texture decoder
// the tools load from <prefix>/lib/orb (orb/cli/runtime_module.h).
std::string runtime_module_folder();

}  // namespace orb::python
