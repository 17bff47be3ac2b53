// Binding render_pass's arguments from the one list that also generates the
// kernel's signature (ORB_RENDER_PASS_ARGUMENTS in
// libtables/include/orb/tables/device_types.h), so no argument position,
// buffer or count is written by hand here.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "device_film.h"
#include "opencl.h"
#include "orb/tables/device_types.h"
#include "scene_layout.h"

namespace orb::render {

// render_pass's argument indices, in the kernel's order.
enum class PassArg : cl_uint {
#define ORB_PASS_ARG_FILM(name, ...) film_##name,
#define ORB_PASS_ARG_TABLE(type, name) name,
#define ORB_PASS_ARG_PARAMS(type, name) name,
    ORB_RENDER_PASS_ARGUMENTS(ORB_PASS_ARG_FILM, ORB_PASS_ARG_TABLE, ORB_PASS_ARG_PARAMS)
#undef ORB_PASS_ARG_FILM
#undef ORB_PASS_ARG_TABLE
#undef ORB_PASS_ARG_PARAMS
    count
};

// The film arguments, which take DeviceFilm::buffers() in order.
inline constexpr std::array kFilmArgs{
#define ORB_FILM_ARG_FILM(name, ...) PassArg::film_##name,
#define ORB_FILM_ARG_OTHER(...)
    ORB_RENDER_PASS_ARGUMENTS(ORB_FILM_ARG_FILM, ORB_FILM_ARG_OTHER, ORB_FILM_ARG_OTHER)
#undef ORB_FILM_ARG_FILM
#undef ORB_FILM_ARG_OTHER
};
static_assert(kFilmArgs.size() == DeviceFilm::kBufferCount, "render_pass takes one argument per film channel");

// How many __constant arguments render_pass has when the scene tables are
// placed in constant memory: one per table (the parameters go by value).
// The device must allow that many (CL_DEVICE_MAX_CONSTANT_ARGS).
#define ORB_COUNT_FILM(...)
#define ORB_COUNT_TABLE(type, name) +1
#define ORB_COUNT_PARAMS(type, name)
inline constexpr cl_uint kSceneTableCount =
    0 ORB_RENDER_PASS_ARGUMENTS(ORB_COUNT_FILM, ORB_COUNT_TABLE, ORB_COUNT_PARAMS);
#undef ORB_COUNT_FILM
#undef ORB_COUNT_TABLE
#undef ORB_COUNT_PARAMS

// One read-only device buffer per scene table.
struct SceneBuffers {
#define ORB_SCENE_BUFFER_FILM(...)
#define ORB_SCENE_BUFFER_TABLE(type, name) cl::Buffer name;
#define ORB_SCENE_BUFFER_PARAMS(type, name)
    ORB_RENDER_PASS_ARGUMENTS(ORB_SCENE_BUFFER_FILM, ORB_SCENE_BUFFER_TABLE, ORB_SCENE_BUFFER_PARAMS)
#undef ORB_SCENE_BUFFER_FILM
#undef ORB_SCENE_BUFFER_TABLE
#undef ORB_SCENE_BUFFER_PARAMS
};

// Bytes the tables take on the device (an empty table still takes one
// placeholder record: OpenCL has no empty buffers).
std::uint64_t scene_table_bytes(const SceneTables& tables);
// The same table by table, in the list's order.
std::vector<std::uint64_t> scene_table_buffer_bytes(const SceneTables& tables);

SceneBuffers upload_scene(const cl::Context& context, const SceneTables& tables);

// The same into `buffers`, keeping each buffer that has the table's size
// and writing the new records into it (frame after frame an animated scene
// keeps its table sizes: no allocation on the device, which costs more than
// the copy for small tables). Blocking: the tables may go away afterwards.
void upload_scene(const cl::Context& context, cl::CommandQueue& queue, const SceneTables& tables,
                  SceneBuffers& buffers);

// Binds the film and the scene tables, which stay for the whole render.
// Throws std::runtime_error if the kernel's argument count is not the list's
// plus `trailing_args` (kernels from --kernel-dir out of step with this
// build). A kernel with trailing arguments after the list's (dev/'s trace_rays)
// binds those itself, from static_cast<cl_uint>(PassArg::count) on.
void bind_buffers(cl::Kernel& kernel, const DeviceFilm& film, const SceneBuffers& scene, cl_uint trailing_args = 0);

// Sets the parameter struct; called before every pass.
void bind_params(cl::Kernel& kernel, const device::RenderPassParams& params);

}  // namespace orb::render
