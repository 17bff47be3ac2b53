// Running the real orb-render (and friends) from tests: exit code, stdout
// and stderr captured through files, and a handle for sending signals.
#pragma once

#include <sys/types.h>

#include <functional>
#include <string>
#include <vector>

namespace orb::test {

struct ProcessResult {
    int exit_code = -1;    // -1 if killed by a signal
    int term_signal = 0;   // the signal that killed it, if any
    std::string out;       // stdout, unless redirected to a file
    std::string err;       // stderr
};

// Runs argv[0] with the arguments; stdin from `stdin_path` ("" = /dev/null),
// stdout into `stdout_path` ("" = captured into ProcessResult::out).
ProcessResult run_process(const std::vector<std::string>& argv, const std::string& stdin_path = "",
                          const std::string& stdout_path = "");

// A process left running, e.g. to interrupt it.
class Child {
public:
    Child(const std::vector<std::string>& argv, const std::string& stderr_path);
    ~Child();  // kills and reaps it if still running
    Child(const Child&) = delete;
    Child& operator=(const Child&) = delete;

    void send_signal(int signal_number);
    bool running();
    // Waits up to `seconds`; on timeout kills it and returns a result with exit_code -1.
    ProcessResult wait(double seconds);

private:
    pid_t pid_ = -1;
    bool reaped_ = false;
    int status_ = 0;
    std::string stderr_path_;
};

std::string read_text(const std::string& path);

// Polls `condition` every 20 ms until it holds or `seconds` pass; returns its last value.
bool eventually(const std::function<bool()>& condition, double seconds);

}  // namespace orb::test
