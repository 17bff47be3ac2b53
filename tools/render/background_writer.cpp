#include "background_writer.h"

#include <utility>

#include "seconds_since.h"

namespace orb::render_cli {

BackgroundWriter::BackgroundWriter(std::size_t max_in_flight) : max_in_flight_(max_in_flight ? max_in_flight : 1) {}

BackgroundWriter::~BackgroundWriter() {
    for (Write& write : in_flight_)
        if (write.thread.joinable()) write.thread.join();
}

void BackgroundWriter::wait_for_oldest() {
    Write& oldest = in_flight_.front();
    if (oldest.thread.joinable()) oldest.thread.join();
    if (*oldest.error && !error_) error_ = *oldest.error;
    spare_.push_back(std::move(oldest.job->image.film));
    spare_encodings_.push_back(std::move(oldest.encoding));
    in_flight_.pop_front();
}

void BackgroundWriter::rethrow_first_error() {
    if (std::exception_ptr error = std::exchange(error_, nullptr)) std::rethrow_exception(error);
}

void BackgroundWriter::finish() {
    const Clock::time_point start = Clock::now();
    while (!in_flight_.empty()) wait_for_oldest();
    waited_ += seconds_since(start);
    rethrow_first_error();
}

void BackgroundWriter::submit(Job job) {
    const Clock::time_point start = Clock::now();
    while (in_flight_.size() >= max_in_flight_) wait_for_oldest();
    waited_ += seconds_since(start);
    rethrow_first_error();
    std::shared_ptr<exr::ExrEncoding> encoding;
    if (spare_encodings_.empty()) {
        encoding = std::make_shared<exr::ExrEncoding>();
    } else {
        encoding = std::move(spare_encodings_.back());
        spare_encodings_.pop_back();
    }
    Write write{std::make_shared<Job>(std::move(job)), std::move(encoding), std::make_shared<std::exception_ptr>(), {}};
    write.thread = std::thread([job = write.job, encoding = write.encoding, error = write.error] {
        try {
            job->output.write(job->image.encode(*encoding));
        } catch (...) {
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

}  // namespace orb::render_cli
