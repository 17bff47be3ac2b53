// --list-devices: every OpenCL device, one line each, on stdout.
#pragma once

#include <ostream>

namespace orb::render_cli {

void print_device_list(std::ostream& out);

}  // namespace orb::render_cli
