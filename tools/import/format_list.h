// orb-import --list-formats, and the warning for options the input's format
// does not take: both read the table of importers (orb/scene/importers.h).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <string_view>

namespace orb::import_tool {

// One line per importer: its name and other --from words, its file names,
// the heading of its options in --help, and its description.
std::string format_list();

// "--radius (PLY input)" for each option given on the command line that
// belongs to another format's group than `format`'s; empty when none.
std::string options_for_other_formats(const CLI::App& app, std::string_view format);

}  // namespace orb::import_tool
