#include "progressive_render.h"

#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "still_render.h"

namespace py = pybind11;

namespace orb::python {
namespace {

// The render runs on its own thread, which never touches Python: Python's
// thread takes what it has made (next) and may stop it (close) at any time.
// Only the newest snapshot waits to be taken: a slow consumer (a notebook
// redrawing its cell) sees fewer snapshots, never stale ones, and the
// render never waits for Python.
class ProgressiveRender {
public:
    ProgressiveRender(const Scene& posed, job::StillSettings settings) {
        Scene with_map;
        const Scene& to_render = scene_to_render(posed, with_map);
        Scene scene = &to_render == &posed ? posed : std::move(with_map);  // Python may change its scene meanwhile
        settings.on_message = [this](job::MessageKind kind, const std::string& message) {
            if (kind == job::MessageKind::Info) return;
            std::lock_guard lock(mutex_);
            warnings_.push_back(message);
        };
        settings.on_snapshot = [this](job::RenderedImage&& snapshot) {
            std::lock_guard lock(mutex_);
            newest_ = std::move(snapshot);
            changed_.notify_all();
        };
        worker_ = std::thread([this, scene = std::move(scene), settings = std::move(settings)] {
            std::optional<job::RenderedImage> image;
            std::exception_ptr error;
            try {
                image = job::render_still(scene, settings, {}, &cancel_);
            } catch (...) {
                error = std::current_exception();
            }
            std::lock_guard lock(mutex_);
            newest_.reset();  // the final image is newer than any snapshot
            final_ = std::move(image);
            error_ = error;
            done_ = true;
            changed_.notify_all();
        });
    }
    ProgressiveRender(const ProgressiveRender&) = delete;
    ProgressiveRender& operator=(const ProgressiveRender&) = delete;
    // Without close() (a generator never started, interpreter exit): the
    // render stops after the pass in flight. The thread never takes the GIL.
    ~ProgressiveRender() { stop(); }

    // The next image (a snapshot, then the final image), or None once the
    // final image was handed out. Raises what the render raised, and
    // KeyboardInterrupt (after stopping the render) on Ctrl-C.
    py::object next() {
        for (;;) {
            std::optional<job::RenderedImage> taken;
            std::vector<std::string> warnings;
            bool finished = false;
            std::exception_ptr error;
            {
                py::gil_scoped_release released;
                std::unique_lock lock(mutex_);
                // Short waits: Python's signal handlers run on this thread, between them.
                changed_.wait_for(lock, std::chrono::milliseconds(50),
                                  [this] { return newest_ || done_ || !warnings_.empty(); });
                warnings.swap(warnings_);
                if (newest_) {
                    taken = std::move(newest_);
                    newest_.reset();
                } else if (done_) {
                    finished = true;
                    taken = std::move(final_);
                    final_.reset();
                    error = error_;
                    error_ = nullptr;
                }
            }
            if (!warnings.empty()) {
                py::module_ warnings_module = py::module_::import("warnings");
                for (const std::string& message : warnings) warnings_module.attr("warn")(message);
            }
            if (PyErr_CheckSignals() != 0) {
                close();
                throw py::error_already_set();
            }
            if (error) {
                close();
                std::rethrow_exception(error);
            }
            if (taken) return py::cast(with_layers(std::move(*taken)));
            if (finished) {
                close();
                return py::none();
            }
        }
    }

    // Stops the render after the pass in flight and waits for its thread.
    void close() {
        py::gil_scoped_release released;
        stop();
    }

private:
    void stop() {
        cancel_ = true;
        if (worker_.joinable()) worker_.join();
    }

    std::mutex mutex_;
    std::condition_variable changed_;
    std::optional<job::RenderedImage> newest_;  // the newest snapshot not taken yet
    std::optional<job::RenderedImage> final_;
    std::exception_ptr error_;
    std::vector<std::string> warnings_;
    bool done_ = false;
    std::atomic<bool> cancel_{false};
    std::thread worker_;  // last: started once everything it uses exists
};

}  // namespace

void bind_progressive_rendering(py::module_& module) {
    py::class_<ProgressiveRender>(module, "_ProgressiveRender")
        .def("next", &ProgressiveRender::next)
        .def("close", &ProgressiveRender::close);
    module.def(
        "_render_progressive",
        [](const Scene& scene, int width, int height, std::uint64_t spp, std::uint64_t seed, const std::string& device,
           const std::vector<std::string>& passes, bool denoise, std::optional<double> target_error,
           std::optional<double> noise_threshold, std::optional<double> time_limit, double every_seconds,
           int every_passes) {
            job::StillSettings settings = still_settings(width, height, spp, seed, device, passes, denoise,
                                                         target_error, noise_threshold, time_limit);
            settings.snapshot_seconds = every_seconds;
            settings.snapshot_passes = every_passes;
            return std::make_unique<ProgressiveRender>(scene, std::move(settings));
        });
}

}  // namespace orb::python
