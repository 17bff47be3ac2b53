// Reading inputs and writing outputs the way every Orb tool does:
// "-" means stdin/stdout, and files are written to a temporary sibling that is
// renamed into place only once complete, so a failed run never leaves a
// partial file and never clobbers a good one.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace orb::cli {

// Whole input as bytes; "-" reads stdin. Throws orb::InputError when unreadable.
std::string read_input(const std::string& path);

// Writes bytes to path atomically ("-" writes stdout).
void write_output(const std::string& path, std::string_view bytes);

// For libraries that insist on writing a file by name (OpenEXR, OIIO):
// write_with calls `writer(temporary_path)` and renames the result into place;
// on any exception the temporary file is removed and the exception rethrown.
// `extension_hint` keeps the temporary's extension so format-by-extension works.
void write_file_atomically(const std::string& path,
                           const std::function<void(const std::string& temporary_path)>& writer);

// Same, but "-" writes the finished temporary file to stdout.
void write_output_via_file(const std::string& path,
                           const std::function<void(const std::string& temporary_path)>& writer,
                           const std::string& stdout_extension = "");

bool is_stdio(const std::string& path);

}  // namespace orb::cli
