// The common shape of an Orb tool's main(): CLI11 parsing with --version and
// -q/--quiet, then the tool's body, with errors mapped to exit codes:
//   0 success, 1 the job failed or the input is bad, 2 usage error.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace orb::cli {

enum ExitCode : int { kSuccess = 0, kFailure = 1, kUsage = 2 };

// A usage problem found after parsing (conflicting options, say).
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Builds the app, lets `configure` add options, parses, runs `body`.
// `body` returns the exit code; exceptions become messages and exit codes.
int run_tool(int argc, char** argv, const std::string& name, const std::string& description,
             const std::function<void(CLI::App&)>& configure, const std::function<int()>& body);

}  // namespace orb::cli
