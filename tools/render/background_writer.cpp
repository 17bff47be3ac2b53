#include "background_writer.h"

#include <chrono>
#include <memory>
#include <utility>

namespace orb::render_cli {

BackgroundWriter::~BackgroundWriter() {
    if (thread_.joinable()) thread_.join();
}

void BackgroundWriter::finish() {
    const auto start = std::chrono::steady_clock::now();
    if (thread_.joinable()) thread_.join();
    waited_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (std::exception_ptr error = std::exchange(error_, nullptr)) std::rethrow_exception(error);
}

void BackgroundWriter::submit(Job job) {
    finish();
    if (current_) spare_ = std::move(current_->image.film);
    current_ = std::make_shared<Job>(std::move(job));
    thread_ = std::thread([this, owned = current_] {
        try {
            owned->output.write(owned->image.encode());
        } catch (...) {
            error_ = std::current_exception();
        }
        owned->claim.reset();  // the frame is on disk (or failed): others may take it now
    });
}

render::Film BackgroundWriter::take_spare_film() {
    if (!thread_.joinable() && current_) spare_ = std::move(current_->image.film);
    return std::exchange(spare_, render::Film{});
}

}  // namespace orb::render_cli
