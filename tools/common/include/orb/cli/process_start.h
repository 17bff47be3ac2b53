// When this process started, on the steady clock: what a start-up time is
// measured from (the loading of the program and its libraries included,
// which a clock read in main() would miss).
#pragma once

#include <chrono>
#include <optional>

namespace orb::cli {

// From the kernel's record of the process's start (/proc/self/stat, in
// clock ticks of 10 ms on most systems); empty where it cannot be read.
std::optional<std::chrono::steady_clock::time_point> process_start();

}  // namespace orb::cli
