// The device compiler lays out the records of device_types.h exactly as the
// host does: a probe kernel, compiled with the embedded header on the default
// device (PoCL here), reports each struct's size and each field's offset.
// The host checks its own side with static_assert; this checks the other.
#define CL_HPP_ENABLE_EXCEPTIONS
#include <CL/opencl.hpp>
#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "orb/tables/device_types.h"
#include "orb/kernels/embedded.h"
#include "orb/render/device.h"
#include "opencl_devices.h"

namespace orb::render::test {
namespace {

struct Probe {
    std::string what;    // "sizeof Type" or "offset of Type.field"
    std::size_t expected;  // the host's figure
};

// The host's figures for every entry of ORB_DEVICE_LAYOUT, in list order.
std::vector<Probe> host_probes()
{
    std::vector<Probe> probes;
#define ORB_HOST_SIZE(type, size) probes.push_back({"sizeof " #type, sizeof(device::type)});
#define ORB_HOST_FIELD(type, field, offset) \
    probes.push_back({"offset of " #type "." #field, offsetof(device::type, field)});
    ORB_DEVICE_LAYOUT(ORB_HOST_SIZE, ORB_HOST_FIELD)
#undef ORB_HOST_SIZE
#undef ORB_HOST_FIELD
    return probes;
}

// A kernel writing the device compiler's figure for each entry, in the same order.
std::string probe_kernel_source()
{
    // device_types.h reads the material kinds' table (its OpenCL side includes nothing).
    std::string source(kernels::find_embedded_kernel("include/orb/tables/material_kinds.h"));
    source += kernels::find_embedded_kernel("include/orb/tables/device_types.h");
    source += "\n__kernel void probe(__global uint* out)\n{\n    int i = 0;\n";
#define ORB_DEVICE_SIZE(type, size) source += "    out[i++] = (uint)sizeof(" #type ");\n";
#define ORB_DEVICE_FIELD(type, field, offset) \
    source += "    { " #type " v; out[i++] = (uint)((__private char*)&v." #field " - (__private char*)&v); }\n";
    ORB_DEVICE_LAYOUT(ORB_DEVICE_SIZE, ORB_DEVICE_FIELD)
#undef ORB_DEVICE_SIZE
#undef ORB_DEVICE_FIELD
    source += "}\n";
    return source;
}

TEST(DeviceLayout, TheDeviceCompilerAgreesWithTheHostOnEverySizeAndOffset)
{
    const DeviceInfo info = choose_device("");
    const cl::Device device = opencl_device(info.index);
    const cl::Context context(device);
    cl::CommandQueue queue(context, device);
    cl::Program program(context, probe_kernel_source());
    try {
        program.build({device}, "-cl-std=CL1.2");
    } catch (const cl::Error&) {
        FAIL() << program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device);
    }

    const std::vector<Probe> probes = host_probes();
    std::vector<cl_uint> out(probes.size(), 0xffffffffu);
    cl::Buffer buffer(context, CL_MEM_WRITE_ONLY, out.size() * sizeof(cl_uint));
    cl::Kernel kernel(program, "probe");
    kernel.setArg(0, buffer);
    queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(1));
    queue.enqueueReadBuffer(buffer, CL_TRUE, 0, out.size() * sizeof(cl_uint), out.data());

    ASSERT_GT(probes.size(), 40u);
    for (std::size_t i = 0; i < probes.size(); ++i) EXPECT_EQ(out[i], probes[i].expected) << probes[i].what;
}

// The enums the kernels compare against keep the values the host stores.
TEST(DeviceLayout, EnumsHaveTheirListedValues)
{
    EXPECT_EQ(static_cast<int>(device::MaterialKind::Diffuse), 0);
    EXPECT_EQ(static_cast<int>(device::MaterialKind::Mirror), 1);
    EXPECT_EQ(static_cast<int>(device::MaterialKind::Dielectric), 2);
    EXPECT_EQ(static_cast<int>(device::MaterialKind::Pbr), 3);
    EXPECT_EQ(static_cast<int>(device::IntegratorMode::Global), 0);
    EXPECT_EQ(static_cast<int>(device::IntegratorMode::Direct), 1);
}

}  // namespace
}  // namespace orb::render::test
