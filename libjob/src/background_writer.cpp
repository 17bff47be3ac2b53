#include "orb/job/background_writer.h"

#include <chrono>
#include <stdexcept>
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

}  // namespace

BackgroundWriter::BackgroundWriter(MessageSink messages, std::size_t max_in_flight)
    : messages_(std::move(messages)), max_in_flight_(max_in_flight ? max_in_flight : 1) {}

BackgroundWriter::~BackgroundWriter() {
    for (Write& write : in_flight_)
        if (write.thread.joinable()) write.thread.join();
}

void BackgroundWriter::wait_for_oldest() {
    Write& oldest = in_flight_.front();
    if (oldest.thread.joinable()) oldest.thread.join();
    if (*oldest.error) failed_.push_back(name_of(*oldest.job));
    spare_.push_back(std::move(oldest.job->image.film));
    spare_encodings_.push_back(std::move(oldest.encoding));
    in_flight_.pop_front();
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
    while (!in_flight_.empty()) wait_for_oldest();
    waited_ += seconds_since(start);
    throw_if_any_failed();
}

void BackgroundWriter::submit(Job job) {
    const Clock::time_point start = Clock::now();
    while (in_flight_.size() >= max_in_flight_) wait_for_oldest();
    // Frames written meanwhile: a failure among them ends the run now, and
    // this frame, rendered but not written, is named with them.
    while (!in_flight_.empty() && in_flight_.front().job.use_count() == 1) wait_for_oldest();
    waited_ += seconds_since(start);
    if (!failed_.empty()) {
        say(messages_, MessageKind::Error, job.label + "not written: the run stops, since " + failed_.front() + " could not be written");
        failed_.push_back(name_of(job));
        throw_if_any_failed();
    }
    std::shared_ptr<exr::ExrEncoding> encoding;
    if (spare_encodings_.empty()) {
        encoding = std::make_shared<exr::ExrEncoding>();
    } else {
        encoding = std::move(spare_encodings_.back());
        spare_encodings_.pop_back();
    }
    Write write{std::make_shared<Job>(std::move(job)), std::move(encoding), std::make_shared<std::exception_ptr>(), {}};
    write.thread = std::thread([job = write.job, encoding = write.encoding, error = write.error, this] {
        // A frame is said to be done once its file is in place, and each
        // frame that fails says why.
        try {
            job->output->write(job->image.encode(*encoding));
            // (Nothing to say for orb-render --benchmark --frames.)
            if (!job->written.empty()) {
                if (job->warn)
                    say(messages_, MessageKind::Warning, job->label + job->written);
                else
                    say(messages_, MessageKind::Info, job->label + job->written);
            }
        } catch (const std::exception& e) {
            say(messages_, MessageKind::Error, job->label + "not written: " + e.what());
            *error = std::current_exception();
        } catch (...) {
            say(messages_, MessageKind::Error, job->label + "not written");
            *error = std::current_exception();
        }
        job->claim.reset();  // the frame is on disk (or failed): others may take it now
    });
    in_flight_.push_back(std::move(write));
}

Film BackgroundWriter::take_spare_film() {
    // A frame already written gives its memory back without waiting for one.
    while (!in_flight_.empty() && spare_.empty()) {
        Write& oldest = in_flight_.front();
        if (oldest.job.use_count() > 1) break;  // its thread still holds the job: still writing
        wait_for_oldest();
    }
    if (spare_.empty()) return {};
    Film film = std::move(spare_.back());
    spare_.pop_back();
    return film;
}

}  // namespace orb::job
