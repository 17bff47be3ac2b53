// The temporary siblings a file output is written to before the rename:
// ".NAME.tmp-PID-RANDOM" beside the output. The pid in the name lets a later
// successful write of the same output remove those left by a process that
// died mid-write (kill -9, a power cut) without touching a live one's.
#pragma once

#include <string>

namespace orb::cli::detail {

// Creates a new temporary sibling of `target` with O_EXCL; returns its
// descriptor and sets `path`. Throws orb::InputError naming `target`.
int create_temporary(const std::string& target, const std::string& option, std::string& path);

// Removes temporaries of `target` whose process no longer exists on this
// host. Best effort: errors are ignored.
void remove_stale_temporaries(const std::string& target) noexcept;

}  // namespace orb::cli::detail
