#include "orb/job/ordered_writes.h"

#include <exception>
#include <utility>

namespace orb::job {

OrderedWrites::OrderedWrites(std::size_t max_in_flight) : max_in_flight_(max_in_flight ? max_in_flight : 1) {}

OrderedWrites::~OrderedWrites() {
    {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [&] { return next_in_place_ == next_sequence_; });
        stopping_ = true;
    }
    changed_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

std::vector<OrderedWrites::Done> OrderedWrites::take_done_locked() {
    std::vector<Done> done;
    while (!slots_.empty() && slots_.front()->state == State::Done) {
        done.push_back({std::move(slots_.front()->write), slots_.front()->written});
        slots_.pop_front();
    }
    return done;
}

std::vector<OrderedWrites::Done> OrderedWrites::submit(std::unique_ptr<Write> write) {
    std::unique_lock<std::mutex> lock(mutex_);
    std::vector<Done> done = take_done_locked();
    while (slots_.size() >= max_in_flight_) {
        changed_.wait(lock, [&] { return slots_.front()->state == State::Done; });
        for (Done& d : take_done_locked()) done.push_back(std::move(d));
    }
    auto slot = std::make_unique<Slot>();
    slot->write = std::move(write);
    slot->sequence = next_sequence_++;
    queued_.push_back(slot.get());
    slots_.push_back(std::move(slot));
    // A worker per write in flight at most, started when more writes wait
    // than workers are free (a free worker may not have woken for the last one yet).
    if (queued_.size() > idle_workers_ && workers_.size() < max_in_flight_) workers_.emplace_back([this] { work(); });
    lock.unlock();
    changed_.notify_all();
    return done;
}

std::vector<OrderedWrites::Done> OrderedWrites::take_done(bool wait) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (wait) changed_.wait(lock, [&] { return next_in_place_ == next_sequence_; });
    return take_done_locked();
}

void OrderedWrites::work() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        ++idle_workers_;
        changed_.wait(lock, [&] { return stopping_ || !queued_.empty(); });
        --idle_workers_;
        if (queued_.empty()) return;  // stopping, nothing left
        Slot& slot = *queued_.front();
        queued_.pop_front();
        slot.state = State::Making;
        lock.unlock();
        write_in_turn(slot);
        lock.lock();
    }
}

void OrderedWrites::write_in_turn(Slot& slot) {
    Write& write = *slot.write;
    std::string why;
    bool ok = true;
    // Every failure names its file (an encoder's error may not).
    const auto failed = [&](const std::string& what) {
        ok = false;
        const std::string name = write.output().display_name();
        why = what.find(name) != std::string::npos ? what
                                                   : name + ": cannot write: " + (what.empty() ? "unknown error" : what);
    };
    std::string_view bytes;
    try {
        bytes = write.make();
        write.output().stage(bytes);
    } catch (const std::exception& e) {
        failed(e.what());
    } catch (...) {
        failed("");
    }
    {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [&] { return next_in_place_ == slot.sequence; });
        if (ok && failed_) {
            ok = false;  // an earlier write failed: this one stays a temporary file, removed with its output
            why.clear();
        }
    }
    // Only this worker's turn now: the calls below run one at a time, in order.
    if (ok) {
        try {
            write.output().commit(bytes);
        } catch (const std::exception& e) {
            failed(e.what());
        } catch (...) {
            failed("");
        }
    }
    try {
        if (ok)
            write.written();
        else
            write.not_written(why);
    } catch (...) {
        // Saying what happened must not stop the writes after it.
    }
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (!ok) failed_ = true;
        slot.written = ok;
        slot.state = State::Done;
        ++next_in_place_;
    }
    changed_.notify_all();
}

}  // namespace orb::job
