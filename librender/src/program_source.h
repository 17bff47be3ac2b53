// The OpenCL C program text: the embedded kernels, or a development folder.
#pragma once

#include <string>

namespace orb::render {

// The kernels' feature defaults (orb/kernels/kernel_features.h), then the
// kernel files in program order. `kernel_dir` empty: the
// ORB_KERNEL_DIR environment variable if set, otherwise the embedded copies.
// Throws std::runtime_error if a file of a kernel folder cannot be read.
std::string program_source(const std::string& kernel_dir);

}  // namespace orb::render
