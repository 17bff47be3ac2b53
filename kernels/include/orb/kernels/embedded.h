// The OpenCL C sources of kernels/, embedded into the binary at build time.
#pragma once

#include <span>
#include <string_view>

namespace orb::kernels {

struct EmbeddedKernel {
    std::string_view file_name;  // relative to kernels/: "rng.cl", "include/orb/tables/device_types.h"
    std::string_view source;
};

// In program order: concatenating them gives the whole program.
std::span<const EmbeddedKernel> embedded_kernels();
// The same for adaptive sampling's decision program (kernels/adaptive.cl).
std::span<const EmbeddedKernel> embedded_decision_kernels();

// The text of one file, or an empty view if there is no such file.
std::string_view find_embedded_kernel(std::string_view file_name);

}  // namespace orb::kernels
