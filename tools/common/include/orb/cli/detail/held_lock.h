// An output's advisory lock as OutputFile holds it (see src/output_lock.h).
#pragma once

#include <string>

namespace orb::cli::detail {

struct HeldLock {
    int fd = -1;        // the flock()ed lock file, -1 when none is held
    std::string path;   // the lock file's path
};

}  // namespace orb::cli::detail
