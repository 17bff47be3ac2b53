#include "orb/job/background_writer.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <utility>

#include "orb/job/seconds_since.h"

namespace orb::job {
namespace {

// "frame 8" (its label without the ": "), or the output's name.
std::string name_of(const BackgroundWriter::Job& job) {
    std::string label = job.label;
    while (!label.empty() && (label.back() == ' ' || label.back() == ':')) label.pop_back();
    return label.empty() ? job.output->display_name() : label;
}

// One frame on the writer's workers: encoded into memory reused from frame
// to frame, said done once its file is in place, its claim released then
// (or once it failed: others may take it).
class FrameWrite final : public OrderedWrites::Write {
public:
    FrameWrite(BackgroundWriter::Job job, std::unique_ptr<exr::ExrEncoding> encoding, const MessageSink& messages)
        : job_(std::move(job)), encoding_(std::move(encoding)), messages_(messages) {}

    ImageOutput& output() override { return *job_.output; }
    std::string_view make() override { return job_.image.encode(*encoding_); }
    void written() override {
        // (Nothing to say for orb-render --benchmark --frames.)
        if (!job_.written.empty())
            say(messages_, job_.warn ? MessageKind::Warning : MessageKind::Info, job_.label + job_.written);
        job_.claim.reset();
    }
    void not_written(const std::string& why) override {
        say(messages_, MessageKind::Error,
            job_.label + "not written: " +
                (why.empty() ? "the run stops, since an earlier frame could not be written" : why));
        job_.claim.reset();
    }

    BackgroundWriter::Job& job() { return job_; }
    std::unique_ptr<exr::ExrEncoding>& encoding() { return encoding_; }

private:
    BackgroundWriter::Job job_;
    std::unique_ptr<exr::ExrEncoding> encoding_;
    const MessageSink& messages_;  // the writer's, which outlives its writes
};

std::uint64_t physical_memory_bytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
    return pages > 0 && page > 0 ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page) : 0;
}

}  // namespace

std::size_t BackgroundWriter::frames_in_flight(std::uint64_t bytes_per_frame) {
    const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
    std::size_t count = std::clamp<std::size_t>(cores, 3, 16);
    const std::uint64_t memory = physical_memory_bytes();
    if (memory > 0 && bytes_per_frame > 0)
        count = std::min<std::size_t>(count, std::max<std::uint64_t>(1, memory / 4 / bytes_per_frame));
    return count;
}

BackgroundWriter::BackgroundWriter(MessageSink messages, std::size_t max_in_flight)
    : messages_(std::move(messages)), writes_(max_in_flight) {}

void BackgroundWriter::take_back(std::vector<OrderedWrites::Done> writes) {
    for (OrderedWrites::Done& done : writes) {
        auto& frame = static_cast<FrameWrite&>(*done.write);
        if (!done.written) failed_.push_back(name_of(frame.job()));
        spare_.push_back(std::move(frame.job().image.film));
        spare_encodings_.push_back(std::move(frame.encoding()));
    }
}

void BackgroundWriter::throw_if_any_failed() {
    if (failed_.empty()) return;
    std::string names;
    for (const std::string& name : failed_) names += (names.empty() ? "" : ", ") + name;
    const std::size_t count = std::exchange(failed_, {}).size();
    throw std::runtime_error(std::to_string(count) + (count == 1 ? " image" : " images") + " not written (" + names +
                             "); those written before stay");
}

void BackgroundWriter::finish() {
    const Clock::time_point start = Clock::now();
    take_back(writes_.take_done(/*wait=*/true));
    waited_ += seconds_since(start);
    throw_if_any_failed();
}

void BackgroundWriter::submit(Job job) {
    // Frames written meanwhile: a failure among them ends the run now, and
    // this frame, rendered but not written, is named with them.
    take_back(writes_.take_done(/*wait=*/false));
    if (!failed_.empty()) {
        say(messages_, MessageKind::Error, job.label + "not written: the run stops, since " + failed_.front() + " could not be written");
        failed_.push_back(name_of(job));
        throw_if_any_failed();
    }
    std::unique_ptr<exr::ExrEncoding> encoding;
    if (spare_encodings_.empty()) {
        encoding = std::make_unique<exr::ExrEncoding>();
    } else {
        encoding = std::move(spare_encodings_.back());
        spare_encodings_.pop_back();
    }
    const Clock::time_point start = Clock::now();
    take_back(writes_.submit(std::make_unique<FrameWrite>(std::move(job), std::move(encoding), messages_)));
    waited_ += seconds_since(start);
}

Film BackgroundWriter::take_spare_film() {
    // A frame already written gives its memory back without waiting for one.
    if (spare_.empty()) take_back(writes_.take_done(/*wait=*/false));
    if (spare_.empty()) return {};
    Film film = std::move(spare_.back());
    spare_.pop_back();
    return film;
}

}  // namespace orb::job
