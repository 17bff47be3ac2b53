#include "orb/cli/process_start.h"

#include <time.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>

namespace orb::cli {

std::optional<std::chrono::steady_clock::time_point> process_start() {
    std::ifstream stat_file("/proc/self/stat");
    std::string text;
    if (!std::getline(stat_file, text)) return std::nullopt;
    // Field 22, starttime, counted after the command's name, which ends at
    // the last ')' and may itself hold spaces and parentheses.
    const std::size_t name_end = text.rfind(')');
    if (name_end == std::string::npos) return std::nullopt;
    std::istringstream fields(text.substr(name_end + 1));
    std::string field;
    for (int index = 3; index <= 22; ++index)
        if (!(fields >> field)) return std::nullopt;
    const long ticks_per_second = ::sysconf(_SC_CLK_TCK);
    timespec boot{};
    if (ticks_per_second <= 0 || ::clock_gettime(CLOCK_BOOTTIME, &boot) != 0) return std::nullopt;
    // starttime counts from boot, as CLOCK_BOOTTIME does: the process's age,
    // taken back from the steady clock's now.
    const auto now = std::chrono::steady_clock::now();
    const double started = std::stod(field) / static_cast<double>(ticks_per_second);
    const double since_boot = static_cast<double>(boot.tv_sec) + static_cast<double>(boot.tv_nsec) * 1e-9;
    const double age = since_boot - started;
    if (age < 0) return std::nullopt;
    return now - std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(age));
}

}  // namespace orb::cli
