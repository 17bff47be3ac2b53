#include "orb/job/frame_claim.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <sstream>

#include "orb/scene/error.h"

namespace orb::job {
namespace {

double now_seconds() {
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

std::string host_name() {
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0) return "unknown-host";
    return name;
}

struct Holder {
    std::string host;
    long pid = 0;
    bool parsed = false;
};

// "host HOST pid PID started UNIX_SECONDS"
Holder read_holder(const std::string& path) {
    Holder holder;
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return holder;
    char buffer[512] = {};
    const ssize_t n = ::read(fd, buffer, sizeof buffer - 1);
    ::close(fd);
    if (n <= 0) return holder;
    std::istringstream in(std::string(buffer, static_cast<std::size_t>(n)));
    std::string host_key, pid_key;
    in >> host_key >> holder.host >> pid_key >> holder.pid;
    holder.parsed = in && host_key == "host" && pid_key == "pid" && holder.pid > 0;
    return holder;
}

std::string describe(const Holder& holder) {
    if (!holder.parsed) return "an unreadable claim";
    return "host " + holder.host + " pid " + std::to_string(holder.pid);
}

// A claim is stale when its process is gone: on this host when the pid no
// longer exists, anywhere when it has not been refreshed for `stale_after`.
bool is_stale(const Holder& holder, const struct stat& info, double stale_after) {
    const double age = now_seconds() - static_cast<double>(info.st_mtim.tv_sec) - info.st_mtim.tv_nsec * 1e-9;
    if (age > stale_after) return true;
    if (holder.parsed && holder.host == host_name())
        return ::kill(static_cast<pid_t>(holder.pid), 0) != 0 && errno == ESRCH;
    return false;
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw InputError(path + ": cannot claim the frame: " + what + ": " + std::strerror(errno));
}

}  // namespace

std::string claim_path(const std::string& output) { return output + ".claim"; }

FrameClaim::FrameClaim(std::string path, int fd) : path_(std::move(path)), fd_(fd) {
    struct stat info {};
    if (::fstat(fd_, &info) == 0) {
        device_ = info.st_dev;
        inode_ = info.st_ino;
    }
    last_refresh_ = now_seconds();
}

std::optional<FrameClaim> FrameClaim::acquire(const std::string& output, double stale_after, std::string& holder) {
    const std::string path = claim_path(output);
    // A few rounds: a stale claim removed by us or by a competitor is raced for again.
    for (int attempt = 0; attempt < 4; ++attempt) {
        const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
        if (fd >= 0) {
            const std::string line = "host " + host_name() + " pid " + std::to_string(::getpid()) + " started " +
                                     std::to_string(static_cast<long long>(now_seconds())) + "\n";
            if (::write(fd, line.data(), line.size()) != static_cast<ssize_t>(line.size())) {
                const int saved = errno;
                ::close(fd);
                ::unlink(path.c_str());
                errno = saved;
                fail(path, "writing the claim");
            }
            return FrameClaim(path, fd);
        }
        if (errno != EEXIST) fail(path, "creating the claim");

        struct stat info {};
        if (::stat(path.c_str(), &info) != 0) {
            if (errno == ENOENT) continue;  // released meanwhile: try again
            fail(path, "reading the claim");
        }
        const Holder current = read_holder(path);
        if (!is_stale(current, info, stale_after)) {
            holder = describe(current);
            return std::nullopt;
        }
        // Take the stale claim away under a name of our own (rename is
        // atomic: of several takers, one succeeds), then check that what we
        // took is the claim judged stale, not a fresh one that replaced it.
        const std::string taken = path + ".stale-" + host_name() + "-" + std::to_string(::getpid());
        if (::rename(path.c_str(), taken.c_str()) != 0) {
            if (errno == ENOENT) continue;
            fail(path, "taking over a stale claim");
        }
        struct stat took {};
        if (::stat(taken.c_str(), &took) == 0 && (took.st_dev != info.st_dev || took.st_ino != info.st_ino))
            (void)::link(taken.c_str(), path.c_str());  // a live claim: give it back (unless yet another came)
        ::unlink(taken.c_str());
    }
    holder = "competing processes";
    return std::nullopt;
}

FrameClaim::FrameClaim(FrameClaim&& other) noexcept { *this = std::move(other); }

FrameClaim& FrameClaim::operator=(FrameClaim&& other) noexcept {
    if (this != &other) {
        release();
        path_ = std::move(other.path_);
        fd_ = other.fd_;
        device_ = other.device_;
        inode_ = other.inode_;
        last_refresh_ = other.last_refresh_;
        other.fd_ = -1;
    }
    return *this;
}

FrameClaim::~FrameClaim() { release(); }

void FrameClaim::refresh() {
    if (fd_ < 0) return;
    const double now = now_seconds();
    if (now - last_refresh_ < 1.0) return;
    last_refresh_ = now;
    (void)::futimens(fd_, nullptr);  // best effort: a missed refresh only risks a takeover after stale_after
}

void FrameClaim::release() noexcept {
    if (fd_ < 0) return;
    struct stat info {};
    if (::stat(path_.c_str(), &info) == 0 && info.st_dev == device_ && info.st_ino == inode_)
        ::unlink(path_.c_str());
    ::close(fd_);
    fd_ = -1;
}

}  // namespace orb::job
