// The OpenCL C program text: the embedded kernels, or a development folder.
#pragma once

#include <string>

namespace orb::render {

// The kernels' feature defaults (orb/tables/kernel_features.h), then the
// kernel files in program order: from `kernel_dir` (the development knob
// ORB_KERNEL_DIR), or the embedded copies when it is empty.
// Throws std::runtime_error if a file of a kernel folder cannot be read.
std::string program_source(const std::string& kernel_dir);

// Adaptive sampling's decision program (kernels/adaptive.cl): its files
// (ORB_DECISION_KERNEL_FILES) in order, from `kernel_dir` or embedded. It
// reads no kernel feature.
std::string decision_program_source(const std::string& kernel_dir);

}  // namespace orb::render
