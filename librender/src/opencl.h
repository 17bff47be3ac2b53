// The one place librender includes the Khronos C++ bindings, so every file
// agrees on the options (exceptions on; OpenCL 1.2 set by the build).
#pragma once

#define CL_HPP_ENABLE_EXCEPTIONS
#include <CL/opencl.hpp>

#include <string>

namespace orb::render {

// "CL_OUT_OF_RESOURCES (-5) in clEnqueueNDRangeKernel" for an error from the bindings.
std::string describe_cl_error(const cl::Error& error);

}  // namespace orb::render
