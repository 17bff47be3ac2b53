// Reading inputs the way every Orb tool does: "-" means stdin. Outputs are
// written through orb::cli::OutputFile (output_file.h), which never destroys
// data, and checked against the inputs with output_overlap.h.
#pragma once

#include <string>

namespace orb::cli {

// Whole input as bytes; "-" reads stdin. Throws orb::InputError when unreadable.
std::string read_input(const std::string& path);

bool is_stdio(const std::string& path);

// Writes `text` (a listing for a shell loop) to stdout and flushes it.
// Returns the tool's exit code: kSuccess, or kFailure after saying "cannot
// write to stdout" when it could not (a closed pipe: every tool ignores
// SIGPIPE, so that is an error, not silence).
int print_to_stdout(const std::string& text);

}  // namespace orb::cli
