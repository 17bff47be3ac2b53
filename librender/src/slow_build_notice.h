#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace orb::render {

// Times one build of the kernels from source and says so, once, when it
// lasts: `notice` is called from a thread of its own once the build has run
// for `delay`, or at finish() when the thread was not scheduled in time, so
// that whether it was said depends only on the measured seconds(), never on
// how busy the machine was. A build spans the compiler and the work the
// driver does at the kernel's first launch (PoCL generates its code there).
class SlowBuildNotice {
public:
    SlowBuildNotice(std::function<void()> notice, std::chrono::milliseconds delay);
    ~SlowBuildNotice();  // finish()es
    SlowBuildNotice(const SlowBuildNotice&) = delete;
    SlowBuildNotice& operator=(const SlowBuildNotice&) = delete;

    // Ends the build's time: says it now if it lasted `delay` or more and
    // was not said yet. Later calls change nothing.
    void finish();
    // The build's seconds so far, or in all once finish()ed.
    double seconds() const;

private:
    using Clock = std::chrono::steady_clock;
    const std::function<void()> notice_;
    const std::chrono::milliseconds delay_;
    const Clock::time_point began_ = Clock::now();
    mutable std::mutex mutex_;
    std::condition_variable ended_;
    bool finished_ = false;
    bool said_ = false;
    Clock::duration lasted_{};
    std::thread waiter_;
};

}  // namespace orb::render
