// An output must never be one of the tool's inputs, nor another output: a
// render written over its own scene, or a report over the image it judges,
// destroys data. Files are compared by device and inode, so "./a.exr",
// "a.exr", a symbolic link and a hard link all count as the same file.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace orb::cli {

struct NamedPath {
    std::string option;  // how the user named it: "SCENE", "-o", "--resume", ...
    std::string path;    // "-" (standard input or output) is never compared
};

// Throws orb::cli::UsageError (exit 2) naming both paths when an output is an
// existing input or two outputs name one file. Outputs that are devices or
// FIFOs are written into, never replaced, and are not compared. `allowed`
// lists (input option, output option) pairs that may be one file, for
// documented in-place updates such as orb-render --resume X -o X.
void refuse_overlapping_paths(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs,
                              const std::vector<std::pair<std::string, std::string>>& allowed = {});

}  // namespace orb::cli
