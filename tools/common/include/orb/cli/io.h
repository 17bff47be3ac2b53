// Reading inputs the way every Orb tool does: "-" means stdin. Outputs are
// written through orb::cli::OutputFile (output_file.h), which never destroys
// data, and checked against the inputs with output_overlap.h.
#pragma once

#include <string>

namespace orb::cli {

// Whole input as bytes; "-" reads stdin. Throws orb::InputError when unreadable.
std::string read_input(const std::string& path);

bool is_stdio(const std::string& path);

}  // namespace orb::cli
