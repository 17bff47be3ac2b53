// The advisory lock that keeps two processes from writing one output: a
// hidden ".NAME.lock" file beside the output, held with flock() for the
// life of the process and removed when released. It holds "PID HOST" of its
// holder. flock() is per host: it does not hold across NFS clients
// (docs/outputs.md).
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

// Removes the lock file of `target` left by a process that died without
// releasing it (kill -9, a crash), when it finds one: a file no process
// holds (flock) that names this host and a pid that no longer exists, or
// an older lock file that names only a pid, which no longer exists. A lock
// of another host, or of a live process, stays. Best effort: errors are
// ignored.
void remove_stale_lock(const std::string& target) noexcept;

}  // namespace orb::cli::detail
