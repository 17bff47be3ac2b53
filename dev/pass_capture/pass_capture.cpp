#include "pass_capture.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace orb::render {
namespace {

void write_file(const std::filesystem::path& path, const void* bytes, std::size_t size)
{
    std::ofstream out(path, std::ios::binary);
    out.write(static_cast<const char*>(bytes), static_cast<std::streamsize>(size));
    if (!out) throw std::runtime_error("capturing a pass: cannot write " + path.string());
}

std::string arg_file(cl_uint index, const char* suffix) { return "arg" + std::to_string(index) + suffix + ".bin"; }

// The buffer's bytes, read back through the queue, as DIR/argN<suffix>.bin.
std::size_t write_buffer(const std::filesystem::path& dir, cl::CommandQueue& queue, cl_uint index,
                         const cl::Buffer& buffer, const char* suffix)
{
    const std::size_t size = buffer.getInfo<CL_MEM_SIZE>();
    std::vector<unsigned char> bytes(size);
    queue.enqueueReadBuffer(buffer, CL_TRUE, 0, size, bytes.data());
    write_file(dir / arg_file(index, suffix), bytes.data(), size);
    return size;
}

}  // namespace

PassCapture::PassCapture(std::string dir, int skip) : dir_(std::move(dir)), skip_(skip) {}

bool PassCapture::pass_launching(cl::CommandQueue& queue, const PassLaunch& launch)
{
    if (taken_ || launch.params.pass.write_centre_ray != 0 || launch.params.pass.sample_count <= 0) return false;
    if (skip_ > 0) {
        --skip_;
        return false;
    }
    taken_ = true;
    write_inputs(queue, launch);
    return true;
}

void PassCapture::write_inputs(cl::CommandQueue& queue, const PassLaunch& launch) const
{
    const std::filesystem::path folder(dir_);
    std::filesystem::create_directories(folder);
    std::ofstream text(folder / "launch.txt");
    text << "kernel " << launch.kernel.getInfo<CL_KERNEL_FUNCTION_NAME>() << '\n'
         << "global " << launch.global[0] << ' ' << launch.global[1] << '\n'
         << "local " << launch.local[0] << ' ' << launch.local[1] << '\n'
         << "options " << launch.program.getBuildInfo<CL_PROGRAM_BUILD_OPTIONS>(queue.getInfo<CL_QUEUE_DEVICE>())
         << '\n';

    const std::vector<std::vector<unsigned char>> binaries = launch.program.getInfo<CL_PROGRAM_BINARIES>();
    if (binaries.size() != 1) throw std::runtime_error("capturing a pass: the program has not one binary");
    write_file(folder / "program.bin", binaries[0].data(), binaries[0].size());

    const auto buffer_line = [&](PassArg arg, const cl::Buffer& buffer, bool film) {
        const cl_uint index = static_cast<cl_uint>(arg);
        const std::size_t size = write_buffer(folder, queue, index, buffer, "");
        text << "arg " << index << (film ? " film " : " buffer ") << size << ' ' << arg_file(index, "") << '\n';
    };
    for (std::size_t i = 0; i < kFilmArgs.size(); ++i) buffer_line(kFilmArgs[i], launch.film.buffers()[i], true);
#define ORB_CAPTURE_FILM(...)
#define ORB_CAPTURE_TABLE(type, name) buffer_line(PassArg::name, launch.scene.name, false);
#define ORB_CAPTURE_PARAMS(type, name)
    ORB_RENDER_PASS_ARGUMENTS(ORB_CAPTURE_FILM, ORB_CAPTURE_TABLE, ORB_CAPTURE_PARAMS)
#undef ORB_CAPTURE_FILM
#undef ORB_CAPTURE_TABLE
#undef ORB_CAPTURE_PARAMS
    const cl_uint params_index = static_cast<cl_uint>(PassArg::params);
    write_file(folder / arg_file(params_index, ""), &launch.params, sizeof launch.params);
    text << "arg " << params_index << " value " << sizeof launch.params << ' ' << arg_file(params_index, "") << '\n';
    // render_pass's argument after the list: the active pixels (a placeholder without adaptive sampling).
    const cl_uint pixels_index = params_index + 1;
    const std::size_t pixels_size = write_buffer(folder, queue, pixels_index, launch.active_pixels, "");
    text << "arg " << pixels_index << " buffer " << pixels_size << ' ' << arg_file(pixels_index, "") << '\n';
    if (!text) throw std::runtime_error("capturing a pass: cannot write " + (folder / "launch.txt").string());
}

void PassCapture::pass_finished(cl::CommandQueue& queue, const PassLaunch& launch)
{
    for (std::size_t i = 0; i < kFilmArgs.size(); ++i)
        write_buffer(dir_, queue, static_cast<cl_uint>(kFilmArgs[i]), launch.film.buffers()[i], ".after");
    std::fprintf(stderr, "orb: captured a pass of %d samples per pixel in %s\n", launch.params.pass.sample_count,
                 dir_.c_str());
}

}  // namespace orb::render
