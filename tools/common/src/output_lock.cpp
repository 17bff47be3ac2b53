#include "output_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "orb/cli/folder_errors.h"
#include "orb/scene/error.h"

namespace orb::cli::detail {
namespace {

namespace fs = std::filesystem;

std::string lock_path_for(const std::string& target) {
    const fs::path p(target);
    std::string name(".");  // appended, not "." + string: GCC 12 warns falsely (-Wrestrict) on that form
    name += p.filename().string();
    name += ".lock";
    return (p.parent_path() / name).string();
}

std::string host_name() {
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0) return "unknown-host";
    return name;
}

// What the lock file says of its holder: "PID HOST" (earlier versions wrote
// the pid alone).
struct Holder {
    long pid = 0;
    std::string host;
};

Holder read_holder(int fd) {
    char buffer[320] = {};
    const ssize_t n = ::pread(fd, buffer, sizeof buffer - 1, 0);
    Holder holder;
    std::istringstream in(n > 0 ? std::string(buffer, static_cast<size_t>(n)) : std::string());
    in >> holder.pid >> holder.host;
    if (!in && !in.eof()) holder.pid = 0;
    return holder;
}

std::string describe(const Holder& holder) {
    if (holder.pid <= 0) return "";
    return " (pid " + std::to_string(holder.pid) + (holder.host.empty() ? "" : " on " + holder.host) + ")";
}

bool process_gone(long pid) { return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }

bool same_inode(int fd, const std::string& path) {
    struct stat open_file {}, on_disk {};
    if (::fstat(fd, &open_file) != 0 || ::stat(path.c_str(), &on_disk) != 0) return false;
    return open_file.st_dev == on_disk.st_dev && open_file.st_ino == on_disk.st_ino;
}

}  // namespace

HeldLock lock_output(const std::string& target, const std::string& option) {
    const std::string path = lock_path_for(target);
    // A holder that releases unlinks the file; whoever locked the unlinked
    // file must try again on the new one.
    for (int attempt = 0; attempt < 100; ++attempt) {
        const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
        if (fd < 0) {
            const int error = errno;
            std::string why = unwritable_folder(fs::path(target).parent_path().string(), error);
            if (why.empty()) why = "cannot create the lock file " + path + ": " + std::strerror(error);
            throw InputError(target + ": cannot write (" + option + "): " + why);
        }
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const int error = errno;
            const Holder holder = read_holder(fd);
            ::close(fd);
            if (error == EWOULDBLOCK)
                throw InputError(target + ": another process" + describe(holder) + " is writing this output (lock " +
                                 path + "); wait for it or choose another " + option);
            throw InputError(target + ": cannot lock " + path + ": " + std::strerror(error));
        }
        if (!same_inode(fd, path)) {
            ::close(fd);
            continue;
        }
        const std::string pid = std::to_string(::getpid()) + " " + host_name() + "\n";
        if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
            const int error = errno;
            ::unlink(path.c_str());
            ::close(fd);
            throw InputError(target + ": cannot write the lock file " + path + ": " + std::strerror(error));
        }
        return {fd, path};
    }
    throw InputError(target + ": cannot lock " + path + ": it keeps being replaced");
}

void remove_stale_lock(const std::string& target) noexcept {
    const std::string path = lock_path_for(target);
    const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0) return;
    // Held by a live process on this host (or being taken right now): not stale.
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        ::close(fd);
        return;
    }
    const Holder holder = read_holder(fd);
    const bool this_host = holder.host.empty() || holder.host == host_name();
    // Unlinked while locked, and only the file that was looked at (a holder
    // that just released it may have left a new one in its place).
    if (this_host && process_gone(holder.pid) && same_inode(fd, path)) ::unlink(path.c_str());
    ::close(fd);
}

void unlock_output(HeldLock& lock) noexcept {
    if (lock.fd < 0) return;
    ::unlink(lock.path.c_str());
    ::close(lock.fd);
    lock.fd = -1;
}

}  // namespace orb::cli::detail
