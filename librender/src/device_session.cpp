#include "device_session.h"

#include <stdexcept>
#include <tuple>
#include <utility>

#include "opencl_devices.h"
#include "program_build.h"
#include "program_source.h"

namespace orb::render {

std::shared_ptr<DeviceSession> DeviceSession::open(const DeviceInfo& device, const SessionOptions& options)
{
    // Sessions live as long as a renderer holds them; the registry only
    // finds a live one again, so a process that renders frame after frame
    // keeps one context and one built program per device.
    static std::mutex mutex;
    static std::map<std::pair<int, SessionOptions>, std::weak_ptr<DeviceSession>> sessions;
    const std::lock_guard<std::mutex> lock(mutex);
    std::weak_ptr<DeviceSession>& slot = sessions[{device.index, options}];
    if (std::shared_ptr<DeviceSession> live = slot.lock()) return live;
    auto session = std::make_shared<DeviceSession>(device, options);
    slot = session;
    return session;
}

DeviceSession::DeviceSession(const DeviceInfo& device, const SessionOptions& options)
    : info_(device), options_(options)
{
    try {
        device_ = opencl_device(info_.index);
        context_ = cl::Context(device_);
        queue_ = cl::CommandQueue(context_, device_);
    } catch (const cl::Error& error) {
        throw std::runtime_error("OpenCL setup on " + info_.name + " failed: " + describe_cl_error(error));
    }
    source_ = program_source(options_.kernel_dir);
}

const cl::Program& DeviceSession::program(const std::string& build_options, const std::function<void()>& on_slow_build,
                                          std::unique_ptr<SlowBuildNotice>* building)
{
    const std::lock_guard<std::mutex> lock(programs_mutex_);
    auto found = programs_.find(build_options);
    if (found != programs_.end()) return found->second;
    ProgramBuild built = build_program(context_, device_, source_, build_options, options_.use_binary_cache,
                                       options_.show_build_log, on_slow_build);
    if (building) *building = std::move(built.building);
    return programs_.emplace(build_options, std::move(built.program)).first->second;
}

cl::CommandQueue& DeviceSession::transfer_queue()
{
    const std::lock_guard<std::mutex> lock(transfer_mutex_);
    if (!transfer_queue_()) transfer_queue_ = cl::CommandQueue(context_, device_);
    return transfer_queue_;
}

const cl::Program* DeviceSession::decision_program()
{
    const std::lock_guard<std::mutex> lock(decision_mutex_);
    if (!decision_tried_) {
        if (device_.getInfo<CL_DEVICE_EXTENSIONS>().find("cl_khr_fp64") != std::string::npos)
            decision_program_ = build_program(context_, device_, decision_program_source(options_.kernel_dir),
                                              kDecisionLanguageOptions, options_.use_binary_cache,
                                              options_.show_build_log)
                                    .program;
        decision_tried_ = true;  // after the build: one that failed throws again
    }
    return decision_program_() ? &decision_program_ : nullptr;
}

int DeviceSession::programs_built() const
{
    const std::lock_guard<std::mutex> lock(programs_mutex_);
    return static_cast<int>(programs_.size());
}

}  // namespace orb::render
