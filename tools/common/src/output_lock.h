// The advisory lock that keeps two processes from writing one output: a
// hidden ".NAME.lock" file beside the output, held with flock() for the
// life of the process and removed when released. flock() is per host: it
// does not hold across NFS clients (docs/outputs.md).
#pragma once

#include <string>

#include "orb/cli/detail/held_lock.h"

namespace orb::cli::detail {

// Locks `target` (a regular file's path, existing or not). Throws
// orb::InputError naming the holder's pid when another process holds it.
HeldLock lock_output(const std::string& target, const std::string& option);

// Removes the lock file, then closes it (in this order, so that a process
// waiting on it cannot lock a file that is about to vanish unnoticed).
void unlock_output(HeldLock& lock) noexcept;

}  // namespace orb::cli::detail
