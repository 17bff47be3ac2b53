// Why a file could not be made in an output's folder, said of the folder
// when the folder is the cause: "the folder ro is not writable" rather than
// the name of a hidden lock or temporary file the user never asked for.
#pragma once

#include <string>

namespace orb::cli {

// For an errno that says the folder refuses new files (EACCES, EPERM,
// EROFS: "the folder ro is not writable (Permission denied)", "... (Read-only
// file system)"), the words that follow "OUT: cannot write (-o): "; empty for
// any other error. An empty `folder` is ".".
std::string unwritable_folder(const std::string& folder, int error);

}  // namespace orb::cli
