#include "device_listing.h"

#include <cstdio>
#include <string>

#include "orb/job/render_job.h"

namespace orb::render_cli {
namespace {

std::string memory_text(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / (1024.0 * 1024.0 * 1024.0));
    return text;
}

}  // namespace

void print_device_list(std::ostream& out) {
    const auto devices = job::list_devices();  // NoOpenCLError says how to install PoCL
    char line[512];
    std::snprintf(line, sizeof line, "%-5s  %-5s  %13s  %10s  %-28s  %s\n", "index", "type", "compute units",
                  "memory", "platform", "device");
    out << line;
    for (const auto& d : devices) {
        std::snprintf(line, sizeof line, "%-5d  %-5s  %13u  %10s  %-28s  %s\n", d.index, d.type.c_str(),
                      d.compute_units, memory_text(d.memory_bytes).c_str(), d.platform.c_str(), d.name.c_str());
        out << line;
    }
    if (devices.empty()) out << "(no OpenCL devices)\n";
}

}  // namespace orb::render_cli
