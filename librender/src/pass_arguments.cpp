#include "pass_arguments.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace orb::render {
namespace {

cl_uint index(PassArg arg) { return static_cast<cl_uint>(arg); }

template <typename T>
std::uint64_t buffer_bytes(const std::vector<T>& records)
{
    return std::max<std::uint64_t>(1, records.size()) * sizeof(T);
}

template <typename T>
cl::Buffer read_only_buffer(const cl::Context& context, const std::vector<T>& records)
{
    static const T placeholder{};  // a table with no records (no lights, say) still needs a buffer
    const void* bytes = records.empty() ? static_cast<const void*>(&placeholder) : records.data();
    return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, buffer_bytes(records),
                      const_cast<void*>(bytes));
}

}  // namespace

std::vector<std::uint64_t> scene_table_buffer_bytes(const SceneTables& tables)
{
    std::vector<std::uint64_t> bytes;
#define ORB_BYTES_FILM(...)
#define ORB_BYTES_TABLE(type, name) bytes.push_back(buffer_bytes(tables.name));
#define ORB_BYTES_PARAMS(type, name)
    ORB_RENDER_PASS_ARGUMENTS(ORB_BYTES_FILM, ORB_BYTES_TABLE, ORB_BYTES_PARAMS)
#undef ORB_BYTES_FILM
#undef ORB_BYTES_TABLE
#undef ORB_BYTES_PARAMS
    return bytes;
}

std::uint64_t scene_table_bytes(const SceneTables& tables)
{
    std::uint64_t total = 0;
    for (std::uint64_t bytes : scene_table_buffer_bytes(tables)) total += bytes;
    return total;
}

SceneBuffers upload_scene(const cl::Context& context, const SceneTables& tables)
{
    SceneBuffers buffers;
#define ORB_UPLOAD_FILM(...)
#define ORB_UPLOAD_TABLE(type, name) buffers.name = read_only_buffer(context, tables.name);
#define ORB_UPLOAD_PARAMS(type, name)
    ORB_RENDER_PASS_ARGUMENTS(ORB_UPLOAD_FILM, ORB_UPLOAD_TABLE, ORB_UPLOAD_PARAMS)
#undef ORB_UPLOAD_FILM
#undef ORB_UPLOAD_TABLE
#undef ORB_UPLOAD_PARAMS
    return buffers;
}

namespace {

template <typename T>
void update_buffer(const cl::Context& context, cl::CommandQueue& queue, const std::vector<T>& records, cl::Buffer& buffer)
{
    if (!buffer() || buffer.getInfo<CL_MEM_SIZE>() != buffer_bytes(records)) {
        buffer = read_only_buffer(context, records);
        return;
    }
    if (!records.empty()) queue.enqueueWriteBuffer(buffer, CL_FALSE, 0, buffer_bytes(records), records.data());
}

}  // namespace

void upload_scene(const cl::Context& context, cl::CommandQueue& queue, const SceneTables& tables, SceneBuffers& buffers)
{
#define ORB_UPDATE_FILM(...)
#define ORB_UPDATE_TABLE(type, name) update_buffer(context, queue, tables.name, buffers.name);
#define ORB_UPDATE_PARAMS(type, name)
    ORB_RENDER_PASS_ARGUMENTS(ORB_UPDATE_FILM, ORB_UPDATE_TABLE, ORB_UPDATE_PARAMS)
#undef ORB_UPDATE_FILM
#undef ORB_UPDATE_TABLE
#undef ORB_UPDATE_PARAMS
    queue.finish();  // the records are the caller's: copied before it goes on
}

void bind_buffers(cl::Kernel& kernel, const DeviceFilm& film, const SceneBuffers& scene, cl_uint trailing_args)
{
    const cl_uint kernel_args = kernel.getInfo<CL_KERNEL_NUM_ARGS>();
    if (kernel_args != index(PassArg::count) + trailing_args)
        throw std::runtime_error("render_pass takes " + std::to_string(kernel_args) + " arguments but this build of " +
                                 "orb binds " + std::to_string(index(PassArg::count) + trailing_args) +
                                 "; do the kernels (--kernel-dir) come from another version?");
    for (std::size_t i = 0; i < kFilmArgs.size(); ++i) kernel.setArg(index(kFilmArgs[i]), film.buffers()[i]);
#define ORB_BIND_FILM(...)
#define ORB_BIND_TABLE(type, name) kernel.setArg(index(PassArg::name), scene.name);
#define ORB_BIND_PARAMS(type, name)
    ORB_RENDER_PASS_ARGUMENTS(ORB_BIND_FILM, ORB_BIND_TABLE, ORB_BIND_PARAMS)
#undef ORB_BIND_FILM
#undef ORB_BIND_TABLE
#undef ORB_BIND_PARAMS
}

void bind_params(cl::Kernel& kernel, const device::RenderPassParams& params)
{
    kernel.setArg(index(PassArg::params), sizeof params, &params);
}

}  // namespace orb::render
