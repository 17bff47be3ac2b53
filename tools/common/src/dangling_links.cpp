#include "dangling_links.h"

#include <sys/stat.h>

#include <filesystem>

#include "orb/scene/error.h"

namespace orb::cli::detail {

std::string follow_dangling_links(const std::string& path) {
    namespace fs = std::filesystem;
    fs::path current(path);
    for (int hops = 0; hops < 40; ++hops) {
        struct stat link {};
        if (::lstat(current.c_str(), &link) != 0 || !S_ISLNK(link.st_mode)) return current.string();
        const fs::path next = fs::read_symlink(current);
        current = next.is_absolute() ? next : current.parent_path() / next;
    }
    throw InputError(path + ": too many levels of symbolic links");
}

}  // namespace orb::cli::detail
