#include "process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <thread>

namespace orb::test {
namespace {

[[noreturn]] void exec_child(const std::vector<std::string>& argv, const std::string& stdin_path,
                             const std::string& stdout_path, const std::string& stderr_path) {
    auto redirect = [](const std::string& path, int fd, int flags) {
        const int opened = ::open(path.c_str(), flags, 0644);
        if (opened < 0) ::_exit(127);
        ::dup2(opened, fd);
        ::close(opened);
    };
    redirect(stdin_path.empty() ? "/dev/null" : stdin_path, STDIN_FILENO, O_RDONLY);
    redirect(stdout_path, STDOUT_FILENO, O_WRONLY | O_CREAT | O_TRUNC);
    redirect(stderr_path, STDERR_FILENO, O_WRONLY | O_CREAT | O_TRUNC);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    ::_exit(127);
}

pid_t spawn(const std::vector<std::string>& argv, const std::string& stdin_path, const std::string& stdout_path,
            const std::string& stderr_path) {
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) exec_child(argv, stdin_path, stdout_path, stderr_path);
    return pid;
}

std::string scratch_file(const char* what) {
    static int counter = 0;
    return (std::filesystem::temp_directory_path() /
            ("orb-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + "." + what))
        .string();
}

void fill_status(ProcessResult& result, int status) {
    if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.term_signal = WTERMSIG(status);
}

}  // namespace

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

ProcessResult run_process(const std::vector<std::string>& argv, const std::string& stdin_path,
                          const std::string& stdout_path) {
    const std::string out_path = stdout_path.empty() ? scratch_file("out") : stdout_path;
    const std::string err_path = scratch_file("err");
    const pid_t pid = spawn(argv, stdin_path, out_path, err_path);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
    }
    ProcessResult result;
    fill_status(result, status);
    result.err = read_text(err_path);
    std::filesystem::remove(err_path);
    if (stdout_path.empty()) {
        result.out = read_text(out_path);
        std::filesystem::remove(out_path);
    }
    return result;
}

Child::Child(const std::vector<std::string>& argv, const std::string& stderr_path) : stderr_path_(stderr_path) {
    pid_ = spawn(argv, "", "/dev/null", stderr_path);
}

Child::~Child() {
    if (!reaped_) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, &status_, 0);
    }
}

void Child::send_signal(int signal_number) { ::kill(pid_, signal_number); }

bool Child::running() {
    if (reaped_) return false;
    if (::waitpid(pid_, &status_, WNOHANG) == pid_) reaped_ = true;
    return !reaped_;
}

ProcessResult Child::wait(double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (running() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ProcessResult result;
    if (running()) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, &status_, 0);
        reaped_ = true;
        result.err = read_text(stderr_path_);
        return result;  // exit_code stays -1
    }
    fill_status(result, status_);
    result.err = read_text(stderr_path_);
    return result;
}

bool eventually(const std::function<bool()>& condition, double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < deadline) {
        if (condition()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return condition();
}

}  // namespace orb::test
