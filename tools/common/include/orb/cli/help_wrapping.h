// Wrapping --help to a width: the terminal's when standard output is one,
// else 80 columns (a pipe, a file, the man pages made from --help). The
// shapes kept are those packaging/cli_reference.py reads back: an option's
// description goes on lines indented past its names, prose goes on lines of
// its own, and an example's comment goes under its command.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace orb::cli {

// The width --help wraps to: the columns of the terminal on standard
// output, else 80 (also when the terminal does not say).
std::size_t help_width();

// `text` broken at spaces into lines of at most `width` characters; a word
// longer than that stands on a line of its own. Runs of spaces between
// words become one.
std::vector<std::string> wrap_words(std::string_view text, std::size_t width);

// One line of a description or a footer, wrapped to `width`:
//  - a line that fits is kept as it is;
//  - prose (no leading space) continues on unindented lines;
//  - an indented line is an example, "  COMMAND   COMMENT": its comment goes
//    under the command, indented further, and a command still too long is
//    continued with " \" on lines indented further, as a shell reads it.
// Returns the lines joined by '\n', without a final one.
std::string wrap_help_line(std::string_view line, std::size_t width);

// `text` wrapped to `width`: unindented lines that follow one another form a
// paragraph, reflowed as one (a line ending in ':' is a heading and stands
// alone); every other line goes through wrap_help_line.
std::string wrap_help_text(std::string_view text, std::size_t width);

}  // namespace orb::cli
