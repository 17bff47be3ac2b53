// Reading inputs the way every Orb tool does: "-" means stdin. Outputs are
// written through orb::cli::OutputFile (output_file.h), which never destroys
// data, and checked against the inputs with output_overlap.h.
#pragma once

#include <stdexcept>
#include <string>

namespace orb::cli {

// Whole input as bytes; "-" reads stdin. Throws orb::InputError when unreadable.
std::string read_input(const std::string& path);

bool is_stdio(const std::string& path);

// Writes `text` (a listing for a shell loop) to stdout and flushes it.
// Returns the tool's exit code: kSuccess, or kFailure after saying "cannot
// write to stdout" when it could not. A reader that closed the pipe early
// (`| head -1`) is not an error: BrokenPipe is thrown.
int print_to_stdout(const std::string& text);

// The reader of standard output, or of a FIFO written as an output, went away
// (EPIPE). Every tool ignores SIGPIPE so that a write failure unwinds the
// stack, removing temporary files and releasing locks; run_tool then ends the
// process by SIGPIPE, quietly, with the status `seq 1 1000000 | head -1` has.
struct BrokenPipe : std::runtime_error {
    explicit BrokenPipe(const std::string& where) : std::runtime_error(where + ": the reader closed the pipe") {}
};

// Throws BrokenPipe naming `where`, and remembers it, so that run_tool still
// ends quietly when a caller has wrapped the exception in another.
[[noreturn]] void throw_broken_pipe(const std::string& where);
bool broken_pipe_seen();

}  // namespace orb::cli
