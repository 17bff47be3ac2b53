#include "orb/cli/paths.h"

#include <filesystem>
#include <system_error>

#include "orb/scene/error.h"

namespace fs = std::filesystem;

namespace orb::cli {

std::string executable_path() {
    std::error_code ec;
    fs::path p = fs::read_symlink("/proc/self/exe", ec);
    return ec ? std::string() : p.string();
}

std::string share_dir() {
    std::error_code ec;
    const std::string exe = executable_path();
    if (!exe.empty()) {
        fs::path candidate = fs::path(exe).parent_path().parent_path() / "share" / "orb";
        if (fs::is_directory(candidate, ec)) return candidate.string();
    }
    throw InputError("cannot find Orb's data folder (expected <install>/share/orb next to <install>/bin)");
}

std::string version_string() { return ORB_VERSION_STRING; }

}  // namespace orb::cli
