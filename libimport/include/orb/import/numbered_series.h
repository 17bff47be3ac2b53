// A numbered series of files as one trajectory: "dump.*.lammpstrj" names
// dump.0.lammpstrj, dump.100.lammpstrj, ... in the order of their numbers,
// as OVITO's wildcard patterns do (docs/orb-render.md, "A numbered series").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace orb {

struct SeriesFile {
    std::string path;          // the folder as the pattern names it, then the file's name
    std::uint64_t number = 0;  // what stands where the pattern's * is
};

// Whether `path` is a series pattern: a `*` in it, and no file of that very name.
bool is_series_pattern(const std::string& path);

// The files `pattern` names, sorted by their number. The pattern has one `*`,
// in its file name (not its folder), standing for a whole number. Throws
// InputError naming the pattern when it has no `*` or more than one, or one
// in the folder; when no file matches; when a name matches around the `*`
// but has no number there (frame.last.xyz), or a number too long to read;
// when two files have the same number (frame.1.xyz, frame.01.xyz); and when a
// file is missing from the series, whose numbers must step evenly (0, 100,
// 200, ...: the first missing one is named).
std::vector<SeriesFile> find_numbered_series(const std::string& pattern);

}  // namespace orb
