#include "pocl_cache_dir.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>

#include "program_build.h"

namespace orb::render {
namespace {

namespace fs = std::filesystem;

// Creates `dir` if needed; true if this process can create files in it.
bool writable_directory(const fs::path& dir)
{
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir, ec)) return false;
    return ::access(dir.c_str(), W_OK | X_OK) == 0;
}

// mkdtemp creates it with mode 0700: no other user can read or plant kernels.
std::string make_private_directory()
{
    const char* tmpdir = std::getenv("TMPDIR");
    std::string pattern = std::string(tmpdir && *tmpdir == '/' ? tmpdir : "/tmp") + "/orb-pocl-XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) return {};
    return pattern;
}

std::string& private_directory()
{
    static std::string path;
    return path;
}

// Registered after nothing of PoCL's is loaded, so it runs after PoCL's own
// exit handlers, when nothing writes into the directory any more.
void remove_private_directory()
{
    std::error_code ec;
    fs::remove_all(private_directory(), ec);
}

}  // namespace

void prepare_pocl_cache_dir()
{
    static std::once_flag once;
    std::call_once(once, [] {
        const char* chosen = std::getenv("POCL_CACHE_DIR");
        if (chosen && *chosen) return;  // the user's choice stands
        const std::string orb_cache = binary_cache_dir();
        if (!orb_cache.empty() && writable_directory(fs::path(orb_cache) / "pocl")) {
            ::setenv("POCL_CACHE_DIR", (orb_cache + "/pocl").c_str(), 0);
            return;
        }
        private_directory() = make_private_directory();
        if (private_directory().empty()) return;  // PoCL will say what it cannot do
        ::setenv("POCL_CACHE_DIR", private_directory().c_str(), 0);
        std::atexit(remove_private_directory);
    });
}

}  // namespace orb::render
