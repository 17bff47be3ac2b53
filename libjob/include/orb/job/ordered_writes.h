// Files made on worker threads, several at once, and put in place in the
// order they were given: a batch of frames whose encoding takes longer than
// rendering keeps every core busy, yet its folder only ever holds the first
// frames of the batch, each whole (a run stopped by a signal or killed
// leaves no later frame without an earlier one, and no partial file).
//
// Each write is made (its bytes) and staged (written beside its target and
// flushed to disk, ImageOutput::stage) on a worker; once every write given
// before it is in place, it is put in place (ImageOutput::commit). After a
// write fails, none given later is put in place: each says so once.
// Memory is bounded: at most `max_in_flight` writes are given and not yet
// taken back (take_done), one worker thread each at most.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "orb/job/image_output.h"

namespace orb::job {

class OrderedWrites {
public:
    // One file to write; its methods run on a worker thread.
    class Write {
    public:
        virtual ~Write() = default;
        virtual ImageOutput& output() = 0;
        // The file's bytes, which must stay valid until the write is taken back.
        virtual std::string_view make() = 0;
        // Called in order, once the file is in place.
        virtual void written() = 0;
        // Called in order, once, when the file is not written: `why` is the
        // error of making, staging or placing it (it names the file), or
        // empty when it was not put in place because an earlier write failed.
        virtual void not_written(const std::string& why) = 0;
    };

    struct Done {
        std::unique_ptr<Write> write;
        bool written = false;
    };

    explicit OrderedWrites(std::size_t max_in_flight);
    OrderedWrites(const OrderedWrites&) = delete;
    OrderedWrites& operator=(const OrderedWrites&) = delete;
    // Waits for every write given, then ends the workers: a batch cut short
    // by an error elsewhere still puts the frames it rendered in place, in order.
    ~OrderedWrites();

    // Gives a write to the workers; first, while `max_in_flight` writes are
    // given and not taken back, waits for the oldest and takes it back.
    // Returns the writes taken back so, oldest first.
    std::vector<Done> submit(std::unique_ptr<Write> write);
    // The writes done so far, oldest first, stopping at the first not done;
    // with `wait`, after waiting for all. Their memory may then be reused.
    std::vector<Done> take_done(bool wait);

    std::size_t max_in_flight() const { return max_in_flight_; }

private:
    enum class State { Queued, Making, Done };
    struct Slot {
        std::unique_ptr<Write> write;
        std::uint64_t sequence = 0;
        State state = State::Queued;
        bool written = false;
    };
    std::vector<Done> take_done_locked();
    void work();
    void write_in_turn(Slot& slot);

    const std::size_t max_in_flight_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::unique_ptr<Slot>> slots_;  // given and not taken back, oldest first
    std::deque<Slot*> queued_;                 // waiting for a worker, oldest first
    std::uint64_t next_sequence_ = 0;
    std::uint64_t next_in_place_ = 0;  // the sequence number whose turn it is to be put in place
    bool failed_ = false;              // a write failed: none after it is put in place
    bool stopping_ = false;
    std::size_t idle_workers_ = 0;
    std::vector<std::thread> workers_;
};

}  // namespace orb::job
