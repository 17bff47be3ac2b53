// Whether a render fits the memory it will use, checked before anything is
// allocated: an allocation that fails inside an OpenCL driver may end the
// process on the spot (PoCL aborts in its buffer migration when the host
// refuses memory), leaving half-written outputs behind, where a clear error
// first lets the tool clean up and say why.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "orb/render/device.h"

namespace orb::render {

// A render that cannot fit: "not enough memory: needs N, has M (...)".
struct NotEnoughMemory : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "3.2 GB", "512 MB", "12 kB", "17 bytes": a size for a message.
std::string byte_text(std::uint64_t bytes);

// Bytes this process can still allocate on the host: the room below its
// address-space limit (RLIMIT_AS, `ulimit -v`) and the memory the system
// has available (MemAvailable and free swap), the smaller; nothing when
// neither is known.
std::optional<std::uint64_t> host_bytes_available();

// What one device of a render holds.
struct DeviceNeeds {
    std::vector<std::uint64_t> buffers;  // each film channel's and scene table's buffer
    std::uint64_t total() const;
};

// Throws NotEnoughMemory when the devices' buffers and `host_bytes` (what
// the host will allocate beside them) do not fit: a buffer larger than its
// device allows, a device's buffers beyond its global memory, or the
// host's part beyond host_bytes_available(). A CPU device's memory is the
// host's (PoCL), so its buffers count there too. `host_available` is
// host_bytes_available() (a parameter for tests).
void require_memory(const std::vector<DeviceInfo>& devices, const std::vector<DeviceNeeds>& needs,
                    std::uint64_t host_bytes, std::optional<std::uint64_t> host_available);

}  // namespace orb::render
