#include "block_workers.h"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>

namespace orb::exr::detail {
namespace {

// One run_blocks call: its jobs are claimed by index, in order.
struct Batch {
    const std::function<void(int)>* job = nullptr;
    int count = 0;
    int next = 0;      // the next index to claim
    int finished = 0;  // indices run (or skipped after an error)
    std::exception_ptr error;
};

class BlockWorkers {
public:
    explicit BlockWorkers(unsigned threads) {
        for (unsigned i = 0; i < threads; ++i) std::thread([this] { work(); }).detach();
    }

    void run(int count, const std::function<void(int)>& job) {
        if (count <= 0) return;
        auto batch = std::make_shared<Batch>();
        batch->job = &job;
        batch->count = count;
        std::unique_lock<std::mutex> lock(mutex_);
        waiting_.push_back(batch);
        lock.unlock();
        work_ready_.notify_all();
        // The caller works on its own blocks until none is left to claim.
        lock.lock();
        while (batch->next < batch->count) run_one(*batch, lock);
        finished_.wait(lock, [&] { return batch->finished == batch->count; });
        if (batch->error) std::rethrow_exception(batch->error);
    }

private:
    // Claims and runs the batch's next job, the lock released meanwhile.
    void run_one(Batch& batch, std::unique_lock<std::mutex>& lock) {
        const int index = batch.next++;
        if (batch.next == batch.count) forget(batch);
        const bool skip = static_cast<bool>(batch.error);
        std::exception_ptr error;
        lock.unlock();
        if (!skip) {
            try {
                (*batch.job)(index);
            } catch (...) {
                error = std::current_exception();
            }
        }
        lock.lock();
        if (error && !batch.error) batch.error = error;
        if (++batch.finished == batch.count) finished_.notify_all();
    }

    // Every job of the batch is claimed: the workers look past it.
    void forget(const Batch& batch) {
        for (auto it = waiting_.begin(); it != waiting_.end(); ++it)
            if (it->get() == &batch) {
                waiting_.erase(it);
                return;
            }
    }

    [[noreturn]] void work() {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            work_ready_.wait(lock, [&] { return !waiting_.empty(); });
            const std::shared_ptr<Batch> batch = waiting_.front();  // kept alive while its job runs
            run_one(*batch, lock);
        }
    }

    std::mutex mutex_;
    std::condition_variable work_ready_, finished_;
    std::deque<std::shared_ptr<Batch>> waiting_;  // batches with jobs left to claim, oldest first
};

}  // namespace

void run_blocks(int count, const std::function<void(int)>& job) {
    // Never destroyed: its threads wait for work until the process ends.
    static BlockWorkers& workers = *new BlockWorkers(std::max(1u, std::thread::hardware_concurrency()) - 1);
    workers.run(count, job);
}

}  // namespace orb::exr::detail
