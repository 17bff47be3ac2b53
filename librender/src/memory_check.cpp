#include "memory_check.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace orb::render {
namespace {

// A field of /proc/meminfo in bytes ("MemAvailable:  123456 kB").
std::optional<std::uint64_t> meminfo_field(const std::string& name)
{
    std::ifstream in("/proc/meminfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind(name + ":", 0) != 0) continue;
        std::istringstream fields(line.substr(name.size() + 1));
        std::uint64_t kilobytes = 0;
        if (fields >> kilobytes) return kilobytes * 1024;
    }
    return std::nullopt;
}

// The bytes this process maps now (VmSize), which count against RLIMIT_AS.
std::optional<std::uint64_t> mapped_bytes()
{
    std::ifstream in("/proc/self/statm");
    std::uint64_t pages = 0;
    if (!(in >> pages)) return std::nullopt;
    return pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

}  // namespace

std::string byte_text(std::uint64_t bytes)
{
    const char* units[] = {"bytes", "kB", "MB", "GB", "TB"};
    double value = static_cast<double>(bytes);
    int unit = 0;
    while (value >= 1000.0 && unit < 4) value /= 1000.0, ++unit;
    char text[32];
    if (unit == 0)
        std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
    else
        std::snprintf(text, sizeof text, value < 10 ? "%.2f %s" : value < 100 ? "%.1f %s" : "%.0f %s", value, units[unit]);
    return text;
}

std::optional<std::uint64_t> host_bytes_available()
{
    std::optional<std::uint64_t> available;
    const auto at_most = [&](std::uint64_t bytes) { available = available ? std::min(*available, bytes) : bytes; };
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
        const std::uint64_t used = mapped_bytes().value_or(0);
        at_most(limit.rlim_cur > used ? limit.rlim_cur - used : 0);
    }
    if (const std::optional<std::uint64_t> memory = meminfo_field("MemAvailable"))
        at_most(*memory + meminfo_field("SwapFree").value_or(0));
    return available;
}

std::uint64_t DeviceNeeds::total() const
{
    std::uint64_t sum = 0;
    for (std::uint64_t bytes : buffers) sum += bytes;
    return sum;
}

void require_memory(const std::vector<DeviceInfo>& devices, const std::vector<DeviceNeeds>& needs,
                    std::uint64_t host_bytes, std::optional<std::uint64_t> host_available)
{
    const auto fail = [](std::uint64_t need, std::uint64_t has, const std::string& where) {
        throw NotEnoughMemory("not enough memory: needs " + byte_text(need) + ", has " + byte_text(has) + " (" +
                              where + ")");
    };
    std::uint64_t host_need = host_bytes;
    for (std::size_t d = 0; d < devices.size() && d < needs.size(); ++d) {
        const DeviceInfo& device = devices[d];
        const std::uint64_t largest =
            needs[d].buffers.empty() ? 0 : *std::max_element(needs[d].buffers.begin(), needs[d].buffers.end());
        if (device.max_allocation_bytes > 0 && largest > device.max_allocation_bytes)
            fail(largest, device.max_allocation_bytes, "the largest buffer " + device.name + " allows, for one film channel");
        if (device.global_memory_bytes > 0 && needs[d].total() > device.global_memory_bytes)
            fail(needs[d].total(), device.global_memory_bytes, "the film and the scene on " + device.name);
        if (device.is_cpu) host_need += needs[d].total();  // PoCL's buffers are host memory
    }
    if (host_available && host_need > *host_available)
        fail(host_need, *host_available, "the film, the scene and the image in this process's memory");
}

}  // namespace orb::render
