// OpenCL devices: listing them and choosing one.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace orb::render {

struct DeviceInfo {
    int index = -1;  // position in list_devices(), across all platforms
    std::string platform;
    std::string name;
    std::string vendor;
    std::string version;  // CL_DEVICE_VERSION
    bool is_gpu = false;
    bool is_cpu = false;
    unsigned compute_units = 0;
    unsigned max_clock_mhz = 0;
    std::uint64_t global_memory_bytes = 0;
    std::uint64_t max_allocation_bytes = 0;  // CL_DEVICE_MAX_MEM_ALLOC_SIZE: the largest one buffer
};

// No OpenCL platform at all; the message tells the user to install PoCL.
struct NoOpenCLError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::vector<DeviceInfo> list_devices();

// "" picks the default: the fastest GPU if any, otherwise a CPU device (PoCL).
// A number picks by index; anything else is a case-insensitive substring of
// the device or platform name. Throws std::runtime_error naming the choices.
DeviceInfo choose_device(const std::string& selector);

// Devices for a selector: one as choose_device() reads it, a comma-separated
// list of those ("0,1"), or "all" (every device). Throws std::runtime_error
// naming the choices for an entry that matches nothing or a device named twice.
std::vector<DeviceInfo> choose_devices(const std::string& selector);

}  // namespace orb::render
