#include "orb/cli/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "dangling_links.h"
#include "orb/cli/io.h"
#include "orb/scene/error.h"
#include "output_lock.h"
#include "temporary_files.h"

namespace orb::cli {
namespace {

namespace fs = std::filesystem;

std::string describe_non_regular(mode_t mode) {
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    return "a special file";
}

std::string folder_of(const std::string& file) {
    const fs::path parent = fs::path(file).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

void write_all(int fd, std::string_view bytes) {
    size_t done = 0;
    while (done < bytes.size()) {
        // Bounded chunks: some devices refuse or split very large writes.
        const size_t chunk = std::min<size_t>(bytes.size() - done, size_t{1} << 24);
        const ssize_t n = ::write(fd, bytes.data() + done, chunk);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw std::system_error(errno, std::generic_category());
        }
        if (n == 0) throw std::system_error(EIO, std::generic_category());
        done += static_cast<size_t>(n);
    }
}

[[noreturn]] void fail_write(const std::string& name, const std::string& option, const std::string& what) {
    throw std::runtime_error(name + ": cannot write (" + option + "): " + what);
}

// Keeps the permissions (and, for root, the owner) of the file being replaced.
void copy_mode_of_existing(const std::string& target, int fd) {
    struct stat existing {};
    if (::stat(target.c_str(), &existing) != 0 || !S_ISREG(existing.st_mode)) return;
    (void)::fchmod(fd, existing.st_mode & 07777);
    if (::geteuid() == 0) (void)::fchown(fd, existing.st_uid, existing.st_gid);
}

void sync_folder(const std::string& file) noexcept {
    const int fd = ::open(folder_of(file).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    (void)::fsync(fd);  // makes the rename durable; some file systems refuse, which is harmless
    ::close(fd);
}

}  // namespace

OutputFile::OutputFile(std::string path, std::string option) : path_(std::move(path)), option_(std::move(option)) {
    if (path_ == "-") {
        kind_ = Kind::Stdout;
        return;
    }
    if (path_.empty()) throw InputError(option_ + ": empty output path");
    struct stat existing {};
    if (::stat(path_.c_str(), &existing) == 0) {
        if (S_ISDIR(existing.st_mode))
            throw InputError(path_ + ": is a directory; " + option_ + " needs a file name");
        if (!S_ISREG(existing.st_mode)) {
            kind_ = Kind::Stream;
            target_ = path_;
            stream_description_ = describe_non_regular(existing.st_mode);
            if (S_ISSOCK(existing.st_mode))
                throw InputError(path_ + ": is a socket; " + option_ + " needs a file, a FIFO or a device");
            if (::access(path_.c_str(), W_OK) != 0)
                throw InputError(path_ + ": cannot write (" + option_ + "): " + std::strerror(errno));
            return;
        }
        char* real = ::realpath(path_.c_str(), nullptr);
        if (!real) throw InputError(path_ + ": cannot resolve (" + option_ + "): " + std::strerror(errno));
        target_ = real;
        std::free(real);
    } else if (errno == ENOENT) {
        target_ = detail::follow_dangling_links(path_);
        struct stat folder {};
        const std::string parent = folder_of(target_);
        if (::stat(parent.c_str(), &folder) != 0 || !S_ISDIR(folder.st_mode))
            throw InputError(path_ + ": cannot write (" + option_ + "): folder " + parent + " does not exist");
    } else {
        throw InputError(path_ + ": cannot write (" + option_ + "): " + std::strerror(errno));
    }
    kind_ = Kind::File;
    held_lock_ = detail::lock_output(target_, option_);
    try {
        open_temporary();
    } catch (...) {
        release();
        throw;
    }
}

OutputFile::~OutputFile() { release(); }

void OutputFile::remove_stale_lock(const std::string& path) noexcept {
    try {
        struct stat existing {};
        if (path.empty() || path == "-") return;
        if (::stat(path.c_str(), &existing) == 0) {
            if (!S_ISREG(existing.st_mode)) return;  // a stream takes no lock
            char* real = ::realpath(path.c_str(), nullptr);
            if (!real) return;
            const std::string target = real;
            std::free(real);
            detail::remove_stale_lock(target);
        } else {
            detail::remove_stale_lock(detail::follow_dangling_links(path));
        }
    } catch (...) {
        // Best effort: a lock left is only a file left.
    }
}

OutputFile::OutputFile(OutputFile&& other) noexcept { *this = std::move(other); }

OutputFile& OutputFile::operator=(OutputFile&& other) noexcept {
    if (this != &other) {
        release();
        path_ = std::move(other.path_);
        option_ = std::move(other.option_);
        kind_ = other.kind_;
        target_ = std::move(other.target_);
        stream_description_ = std::move(other.stream_description_);
        held_lock_ = std::exchange(other.held_lock_, {});
        temp_fd_ = std::exchange(other.temp_fd_, -1);
        temp_path_ = std::exchange(other.temp_path_, {});
    }
    return *this;
}

std::string OutputFile::display_name() const { return kind_ == Kind::Stdout ? std::string("<stdout>") : path_; }

void OutputFile::open_temporary() { temp_fd_ = detail::create_temporary(target_, option_, temp_path_); }

void OutputFile::discard_temporary() noexcept {
    if (temp_fd_ >= 0) ::close(temp_fd_);
    if (!temp_path_.empty()) ::unlink(temp_path_.c_str());
    temp_fd_ = -1;
    temp_path_.clear();
}

void OutputFile::release() noexcept {
    discard_temporary();
    detail::unlock_output(held_lock_);
}

void OutputFile::write_stream(std::string_view bytes) {
    if (kind_ == Kind::Stdout) {
        try {
            write_all(STDOUT_FILENO, bytes);
        } catch (const std::system_error& e) {
            if (e.code().value() == EPIPE) throw_broken_pipe("<stdout>");
            fail_write("<stdout>", option_, std::strerror(e.code().value()));
        }
        return;
    }
    if (kind_ == Kind::Stream) {
        // No O_CREAT: if the node vanished, fail rather than leave a regular file in its place.
        const int fd = ::open(target_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
        if (fd < 0) fail_write(path_, option_, std::strerror(errno));
        try {
            write_all(fd, bytes);
        } catch (const std::system_error& e) {
            ::close(fd);
            if (e.code().value() == EPIPE) throw_broken_pipe(path_);
            fail_write(path_, option_, std::strerror(e.code().value()));
        }
        if (::close(fd) != 0) fail_write(path_, option_, std::strerror(errno));
    }
}

void OutputFile::write(std::string_view bytes) {
    stage(bytes);
    commit(bytes);
}

void OutputFile::stage(std::string_view bytes) {
    if (kind_ != Kind::File) return;  // a stream is written by commit(), in its turn
    if (temp_fd_ < 0) {
        discard_temporary();  // one staged and never put in place
        open_temporary();
    }
    // Every step is checked: a full disk or a quota may only show at fsync or close.
    const auto fail = [&](const char* step, int error) {
        discard_temporary();
        fail_write(path_, option_, std::string(step) + std::strerror(error));
    };
    try {
        write_all(temp_fd_, bytes);
    } catch (const std::system_error& e) {
        fail("", e.code().value());
    }
    copy_mode_of_existing(target_, temp_fd_);
    if (::fsync(temp_fd_) != 0) fail("flushing to disk: ", errno);
    const int fd = std::exchange(temp_fd_, -1);
    if (::close(fd) != 0) fail("closing: ", errno);
}

void OutputFile::commit(std::string_view bytes) {
    if (kind_ != Kind::File) {
        write_stream(bytes);
        return;
    }
    if (temp_path_.empty() || temp_fd_ >= 0) throw std::logic_error(path_ + ": put in place before it was staged");
    if (::rename(temp_path_.c_str(), target_.c_str()) != 0) {
        const int error = errno;
        discard_temporary();
        fail_write(path_, option_, std::string("renaming into place: ") + std::strerror(error));
    }
    temp_path_.clear();
    sync_folder(target_);
    detail::remove_stale_temporaries(target_);
}

}  // namespace orb::cli
