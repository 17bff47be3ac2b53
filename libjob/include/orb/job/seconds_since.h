// The steady clock the render job's timings read (frames, background
// writes, the frames benchmark), and the seconds elapsed on it.
#pragma once

#include <chrono>

namespace orb::job {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace orb::job
