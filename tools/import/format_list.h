// orb-import --list-formats, from the table of importers (orb/import/importers.h).
#pragma once

#include <string>

namespace orb::import_tool {

// One line per importer: its name and other --from words, its file names,
// the heading of its options in --help, and its description.
std::string format_list();

}  // namespace orb::import_tool
