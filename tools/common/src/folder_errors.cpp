#include "orb/cli/folder_errors.h"

#include <cerrno>
#include <cstring>

namespace orb::cli {

std::string unwritable_folder(const std::string& folder, int error) {
    const std::string shown = folder.empty() ? std::string(".") : folder;
    if (error == EACCES || error == EPERM) return "the folder " + shown + " is not writable (" + std::strerror(error) + ")";
    if (error == EROFS) return "the folder " + shown + " is on a read-only file system";
    return {};
}

}  // namespace orb::cli
