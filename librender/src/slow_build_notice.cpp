#include "slow_build_notice.h"

#include <utility>

namespace orb::render {

SlowBuildNotice::SlowBuildNotice(std::function<void()> notice, std::chrono::milliseconds delay)
    : notice_(std::move(notice)), delay_(delay)
{
    if (!notice_) return;
    waiter_ = std::thread([this] {
        std::unique_lock<std::mutex> lock(mutex_);
        if (ended_.wait_until(lock, began_ + delay_, [this] { return finished_; })) return;
        said_ = true;
        lock.unlock();
        notice_();
    });
}

SlowBuildNotice::~SlowBuildNotice() { finish(); }

void SlowBuildNotice::finish()
{
    bool say_now = false;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (finished_) return;
        finished_ = true;
        lasted_ = Clock::now() - began_;
        say_now = notice_ && !said_ && lasted_ >= delay_;
        said_ = said_ || say_now;
    }
    ended_.notify_all();
    if (waiter_.joinable()) waiter_.join();
    if (say_now) notice_();
}

double SlowBuildNotice::seconds() const
{
    const std::lock_guard<std::mutex> lock(mutex_);
    return std::chrono::duration<double>(finished_ ? lasted_ : Clock::now() - began_).count();
}

}  // namespace orb::render
