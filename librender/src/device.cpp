// Enumerating OpenCL devices and choosing one.
#include <algorithm>
#include <cctype>
#include <mutex>
#include <sstream>

#include "opencl_devices.h"
#include "pocl_cache_dir.h"

namespace orb::render {
namespace {

const char* const kInstallPocl =
    "no OpenCL platform found: install an OpenCL driver; PoCL runs on any CPU "
    "(Debian/Ubuntu: apt-get install pocl-opencl-icd)";

std::vector<cl::Platform> platforms_or_throw()
{
    prepare_pocl_cache_dir();  // before PoCL loads, or it may offer no platform
    std::vector<cl::Platform> platforms;
    try {
        cl::Platform::get(&platforms);
    } catch (const cl::Error&) {
        platforms.clear();  // the ICD loader reports "no platform" as an error
    }
    if (platforms.empty()) throw NoOpenCLError(kInstallPocl);
    return platforms;
}

std::vector<cl::Device> devices_of(const cl::Platform& platform)
{
    std::vector<cl::Device> devices;
    try {
        platform.getDevices(CL_DEVICE_TYPE_ALL, &devices);
    } catch (const cl::Error&) {
        devices.clear();  // CL_DEVICE_NOT_FOUND: a platform without devices
    }
    return devices;
}

std::vector<std::pair<cl::Platform, cl::Device>> enumerate_devices()
{
    std::vector<std::pair<cl::Platform, cl::Device>> out;
    for (const cl::Platform& platform : platforms_or_throw())
        for (const cl::Device& device : devices_of(platform)) out.emplace_back(platform, device);
    return out;
}

// All devices in list order, with their platforms. The ICD loader and PoCL
// set themselves up during the first enumeration, which is not safe from
// several threads at once (renders started together on an embedding's
// threads crashed there, or found no platform): the first one runs alone,
// the others wait for it (and try again if it threw).
std::vector<std::pair<cl::Platform, cl::Device>> all_devices()
{
    static std::once_flag set_up;
    std::call_once(set_up, [] { (void)enumerate_devices(); });
    return enumerate_devices();
}

std::string lowercase(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

std::string trimmed(std::string text)
{
    while (!text.empty() && (std::isspace(static_cast<unsigned char>(text.back())) || text.back() == '\0'))
        text.pop_back();
    return text;
}

std::string choices_text(const std::vector<DeviceInfo>& devices)
{
    std::ostringstream out;
    for (const DeviceInfo& d : devices) out << "\n  " << d.index << ": " << d.name << " (" << d.platform << ")";
    return out.str();
}

double speed_score(const DeviceInfo& d) { return static_cast<double>(d.compute_units) * d.max_clock_mhz; }

}  // namespace

std::vector<DeviceInfo> list_devices()
{
    std::vector<DeviceInfo> out;
    for (const auto& [platform, device] : all_devices()) {
        DeviceInfo info;
        info.index = static_cast<int>(out.size());
        info.platform = trimmed(platform.getInfo<CL_PLATFORM_NAME>());
        info.name = trimmed(device.getInfo<CL_DEVICE_NAME>());
        info.vendor = trimmed(device.getInfo<CL_DEVICE_VENDOR>());
        info.version = trimmed(device.getInfo<CL_DEVICE_VERSION>());
        const cl_device_type type = device.getInfo<CL_DEVICE_TYPE>();
        info.is_gpu = (type & CL_DEVICE_TYPE_GPU) != 0;
        info.is_cpu = (type & CL_DEVICE_TYPE_CPU) != 0;
        info.compute_units = device.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
        info.max_clock_mhz = device.getInfo<CL_DEVICE_MAX_CLOCK_FREQUENCY>();
        info.global_memory_bytes = device.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
        info.max_allocation_bytes = device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
        out.push_back(std::move(info));
    }
    if (out.empty()) throw NoOpenCLError(kInstallPocl);
    return out;
}

DeviceInfo choose_device(const std::string& selector)
{
    const std::vector<DeviceInfo> devices = list_devices();
    if (selector.empty()) {
        const DeviceInfo* best_gpu = nullptr;
        for (const DeviceInfo& d : devices)
            if (d.is_gpu && (!best_gpu || speed_score(d) > speed_score(*best_gpu))) best_gpu = &d;
        if (best_gpu) return *best_gpu;
        for (const DeviceInfo& d : devices)
            if (d.is_cpu) return d;
        return devices.front();
    }
    if (std::all_of(selector.begin(), selector.end(), [](unsigned char c) { return std::isdigit(c); })) {
        const long index = selector.size() <= 9 ? std::stol(selector) : -1;
        if (index < 0 || index >= static_cast<long>(devices.size()))
            throw std::runtime_error("no OpenCL device with index " + selector + "; the devices are:" +
                                     choices_text(devices));
        return devices[static_cast<size_t>(index)];
    }
    const std::string wanted = lowercase(selector);
    for (const DeviceInfo& d : devices)
        if (lowercase(d.name).find(wanted) != std::string::npos ||
            lowercase(d.platform).find(wanted) != std::string::npos)
            return d;
    throw std::runtime_error("no OpenCL device matches '" + selector + "'; the devices are:" + choices_text(devices));
}

std::vector<DeviceInfo> choose_devices(const std::string& selector)
{
    if (lowercase(selector) == "all") return list_devices();
    if (selector.find(',') == std::string::npos) return {choose_device(selector)};
    std::vector<DeviceInfo> chosen;
    std::size_t start = 0;
    while (start <= selector.size()) {
        std::size_t comma = selector.find(',', start);
        if (comma == std::string::npos) comma = selector.size();
        const std::string entry = selector.substr(start, comma - start);
        start = comma + 1;
        if (entry.empty()) throw std::runtime_error("--device " + selector + ": an empty entry in the list");
        DeviceInfo device = choose_device(entry);
        for (const DeviceInfo& d : chosen)
            if (d.index == device.index)
                throw std::runtime_error("--device " + selector + ": device " + std::to_string(d.index) + " (" +
                                         d.name + ") is named twice");
        chosen.push_back(std::move(device));
    }
    return chosen;
}

cl::Device opencl_device(int index)
{
    const auto devices = all_devices();
    if (index < 0 || index >= static_cast<int>(devices.size()))
        throw std::runtime_error("OpenCL device " + std::to_string(index) + " is no longer available");
    return devices[static_cast<size_t>(index)].second;
}

}  // namespace orb::render
