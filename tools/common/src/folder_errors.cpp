#include "orb/cli/folder_errors.h"

#include <cerrno>
#include <cstring>

namespace orb::cli {

std::string unwritable_folder(const std::string& folder, int error) {
    const std::string shown = folder.empty() ? std::string(".") : folder;
    if (error != EACCES && error != EPERM && error != EROFS) return {};
    return "the folder " + shown + " is not writable (" + std::strerror(error) + ")";
}

}  // namespace orb::cli
