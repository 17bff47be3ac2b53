// Runs a real executable the way a shell would, for CLI tests: given
// arguments and stdin bytes, returns its exit code, stdout and stderr.
#pragma once

#include <string>
#include <vector>

namespace orb::test {

struct ProcessResult {
    int exit_code = -1;  // 128 + signal number when killed by a signal
    std::string out;
    std::string err;
};

// stdin, stdout and stderr go through temporary files, so large outputs
// cannot deadlock a pipe. `working_dir` is where the process runs.
ProcessResult run_process(const std::string& executable, const std::vector<std::string>& arguments,
                          const std::string& stdin_bytes = "", const std::string& working_dir = ".");

}  // namespace orb::test
