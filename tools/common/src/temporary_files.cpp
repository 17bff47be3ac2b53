#include "temporary_files.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#include "orb/cli/folder_errors.h"
#include "orb/scene/error.h"

namespace orb::cli::detail {
namespace {

namespace fs = std::filesystem;

std::string prefix_for(const fs::path& target) {
    std::string prefix(".");  // appended, not "." + string: GCC 12 warns falsely (-Wrestrict) on that form
    prefix += target.filename().string();
    prefix += ".tmp-";
    return prefix;
}

bool process_is_gone(pid_t pid) { return ::kill(pid, 0) != 0 && errno == ESRCH; }

}  // namespace

int create_temporary(const std::string& target, const std::string& option, std::string& path) {
    const fs::path t(target);
    std::random_device entropy;
    for (int attempt = 0; attempt < 16; ++attempt) {
        char suffix[48];
        std::snprintf(suffix, sizeof suffix, "%ld-%08x", static_cast<long>(::getpid()),
                      static_cast<unsigned>(entropy()));
        path = (t.parent_path() / (prefix_for(t) + suffix)).string();
        const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
        if (fd >= 0) return fd;
        if (errno != EEXIST) {
            const int error = errno;
            const std::string folder = t.parent_path().empty() ? std::string(".") : t.parent_path().string();
            std::string why = unwritable_folder(folder, error);
            if (why.empty()) why = "cannot create a file in " + folder + ": " + std::strerror(error);
            throw InputError(target + ": cannot write (" + option + "): " + why);
        }
    }
    throw InputError(target + ": cannot create a temporary file beside it");
}

void remove_stale_temporaries(const std::string& target) noexcept {
    try {
        const fs::path t(target);
        const std::string prefix = prefix_for(t);
        const fs::path folder = t.parent_path().empty() ? fs::path(".") : t.parent_path();
        std::error_code ec;
        for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec)) {
            const std::string name = entry.path().filename().string();
            if (name.compare(0, prefix.size(), prefix) != 0) continue;
            const char* first = name.data() + prefix.size();
            const char* last = name.data() + name.size();
            long pid = 0;
            const auto [end, error] = std::from_chars(first, last, pid);
            if (error != std::errc() || end == first || end == last || *end != '-' || pid <= 0) continue;
            if (pid == ::getpid() || !process_is_gone(static_cast<pid_t>(pid))) continue;
            if (entry.is_regular_file(ec)) fs::remove(entry.path(), ec);
        }
    } catch (...) {
        // Tidying is a courtesy; it must never fail a write that succeeded.
    }
}

}  // namespace orb::cli::detail
