// The OpenCL objects behind DeviceInfo (internal to librender).
#pragma once

#include "opencl.h"
#include "orb/render/device.h"

namespace orb::render {

// The device list_devices() numbered `index`; throws if it is gone.
cl::Device opencl_device(int index);

}  // namespace orb::render
