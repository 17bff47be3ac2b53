// A device opened for rendering, shared by every renderer on it: the OpenCL
// context and queue, and the render_pass programs built for it. Opening the
// same device twice in a process gives the same session, and a program is
// built (or loaded from the binary cache) once per set of build options, so
// frame after frame and renderer after renderer reuse it.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>

#include "opencl.h"
#include "orb/render/device.h"
#include "slow_build_notice.h"

namespace orb::render {

struct SessionOptions {
    std::string kernel_dir;        // "" = the embedded kernels (the development knob ORB_KERNEL_DIR)
    bool use_binary_cache = true;  // $XDG_CACHE_HOME/orb (or ~/.cache/orb)
    bool show_build_log = false;   // the development knob ORB_SHOW_BUILD_LOG
    bool operator<(const SessionOptions& o) const
    {
        return std::tie(kernel_dir, use_binary_cache, show_build_log) <
               std::tie(o.kernel_dir, o.use_binary_cache, o.show_build_log);
    }
};

class DeviceSession {
public:
    // The process's session on `device` with `options`, opened on first use.
    // Throws std::runtime_error when the device cannot be set up.
    static std::shared_ptr<DeviceSession> open(const DeviceInfo& device, const SessionOptions& options);

    DeviceSession(const DeviceInfo& device, const SessionOptions& options);
    DeviceSession(const DeviceSession&) = delete;
    DeviceSession& operator=(const DeviceSession&) = delete;

    const DeviceInfo& info() const { return info_; }
    const SessionOptions& options() const { return options_; }
    // The kernels' program text (program_source.h), for development code
    // that builds a program of its own from it plus kernels of its own.
    const std::string& source() const { return source_; }
    const cl::Device& device() const { return device_; }
    const cl::Context& context() const { return context_; }
    cl::CommandQueue& queue() { return queue_; }
    // A second queue for reading films back while the first renders the
    // next frame (devices with copy engines run both at once). Made on
    // first use.
    cl::CommandQueue& transfer_queue();

    // The program built from the kernels with these compiler options; built
    // on the first request, then the same one. Throws std::runtime_error with
    // the build log when it does not build. `on_slow_build`: see build_program;
    // `building`, when given, receives a build from source's notice, still
    // timing, for the caller to finish() after the kernel's first launch.
    const cl::Program& program(const std::string& build_options, const std::function<void()>& on_slow_build = {},
                               std::unique_ptr<SlowBuildNotice>* building = nullptr);

    // Programs built or loaded so far (one per distinct set of options).
    int programs_built() const;

    // Adaptive sampling's decision program (kernels/adaptive.cl), built on
    // the first request; null on a device without double precision
    // (cl_khr_fp64), where the decisions stay on the host. Throws
    // std::runtime_error with the build log when it does not build.
    const cl::Program* decision_program();

private:
    DeviceInfo info_;
    SessionOptions options_;
    cl::Device device_;
    cl::Context context_;
    cl::CommandQueue queue_;
    std::mutex transfer_mutex_;
    cl::CommandQueue transfer_queue_;
    std::string source_;  // read once: the kernels do not change while the process runs
    mutable std::mutex programs_mutex_;
    std::map<std::string, cl::Program> programs_;
    std::mutex decision_mutex_;
    bool decision_tried_ = false;
    cl::Program decision_program_;  // null until built, and where the device has no fp64
};

}  // namespace orb::render
