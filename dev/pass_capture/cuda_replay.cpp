// Not a test: runs a render pass that orb-capture-pass captured (pass_capture.h
// beside this) again through CUDA's driver API, so that
// Nsight Compute, which does not see OpenCL kernels, can profile the same
// program (what it showed: docs/design/speculative-traversal.md,
// docs/design/register-caps.md).
// NVIDIA's OpenCL binaries are PTX; this loads that PTX with the register
// cap of its build options, binds the captured buffers in order, launches
// the pass with the captured work sizes and checks that the film it leaves
// equals the one OpenCL left, bit for bit, before it times anything.
//
//   orb-cuda-replay DIR [--repeat N]
//
// libcuda is opened at run time (no CUDA headers or toolkit needed to build);
// the few driver API entry points used are declared below as the driver's
// C ABI defines them.
#include <dlfcn.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "orb/tables/device_types.h"

namespace {

using CUresult = int;
using CUdevice = int;
using CUdeviceptr = unsigned long long;
using CUcontext = struct CUctx_st*;
using CUmodule = struct CUmod_st*;
using CUfunction = struct CUfunc_st*;
using CUstream = struct CUstream_st*;

// Values of the driver's CUjit_option and CUfunction_attribute enums.
constexpr int kJitMaxRegisters = 0;
constexpr int kJitInfoLog = 3, kJitInfoLogSize = 4, kJitErrorLog = 5, kJitErrorLogSize = 6;
constexpr int kAttrLocalBytes = 3, kAttrRegisters = 4;

struct Driver {
    CUresult (*cuInit)(unsigned);
    CUresult (*cuDeviceGet)(CUdevice*, int);
    CUresult (*cuDeviceGetName)(char*, int, CUdevice);
    CUresult (*cuCtxCreate)(CUcontext*, unsigned, CUdevice);
    CUresult (*cuModuleLoadDataEx)(CUmodule*, const void*, unsigned, int*, void**);
    CUresult (*cuModuleGetFunction)(CUfunction*, CUmodule, const char*);
    CUresult (*cuFuncGetAttribute)(int*, int, CUfunction);
    CUresult (*cuOccupancyMaxActiveBlocksPerMultiprocessor)(int*, CUfunction, int, std::size_t);
    CUresult (*cuMemAlloc)(CUdeviceptr*, std::size_t);
    CUresult (*cuMemcpyHtoD)(CUdeviceptr, const void*, std::size_t);
    CUresult (*cuMemcpyDtoH)(void*, CUdeviceptr, std::size_t);
    CUresult (*cuLaunchKernel)(CUfunction, unsigned, unsigned, unsigned, unsigned, unsigned, unsigned, unsigned,
                               CUstream, void**, void**);
    CUresult (*cuCtxSynchronize)();
    CUresult (*cuGetErrorString)(CUresult, const char**);
};

template <typename F>
void resolve(void* library, F& function, const char* name)
{
    function = reinterpret_cast<F>(dlsym(library, name));
    if (!function) throw std::runtime_error(std::string("libcuda has no ") + name);
}

Driver open_driver()
{
    void* library = dlopen("libcuda.so.1", RTLD_NOW);
    if (!library) library = dlopen("/usr/local/nvidia/lib64/libcuda.so.1", RTLD_NOW);
    if (!library) throw std::runtime_error(std::string("cannot open libcuda.so.1: ") + dlerror());
    Driver d{};
    resolve(library, d.cuInit, "cuInit");
    resolve(library, d.cuDeviceGet, "cuDeviceGet");
    resolve(library, d.cuDeviceGetName, "cuDeviceGetName");
    resolve(library, d.cuCtxCreate, "cuCtxCreate_v2");
    resolve(library, d.cuModuleLoadDataEx, "cuModuleLoadDataEx");
    resolve(library, d.cuModuleGetFunction, "cuModuleGetFunction");
    resolve(library, d.cuFuncGetAttribute, "cuFuncGetAttribute");
    resolve(library, d.cuOccupancyMaxActiveBlocksPerMultiprocessor, "cuOccupancyMaxActiveBlocksPerMultiprocessor");
    resolve(library, d.cuMemAlloc, "cuMemAlloc_v2");
    resolve(library, d.cuMemcpyHtoD, "cuMemcpyHtoD_v2");
    resolve(library, d.cuMemcpyDtoH, "cuMemcpyDtoH_v2");
    resolve(library, d.cuLaunchKernel, "cuLaunchKernel");
    resolve(library, d.cuCtxSynchronize, "cuCtxSynchronize");
    resolve(library, d.cuGetErrorString, "cuGetErrorString");
    return d;
}

const Driver* g_driver = nullptr;

void check(CUresult result, const char* what)
{
    if (result == 0) return;
    const char* text = "unknown error";
    if (g_driver) g_driver->cuGetErrorString(result, &text);
    throw std::runtime_error(std::string(what) + " failed: " + text + " (" + std::to_string(result) + ")");
}

std::vector<char> read_file(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path);
    return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

struct Argument {
    int index = 0;
    std::string kind;  // film, buffer or value
    std::size_t bytes = 0;
    std::string file;
    std::vector<char> data;
    CUdeviceptr device = 0;
};

struct Launch {
    std::string kernel;
    unsigned global[2]{}, local[2]{};
    int register_cap = 0;  // 0: the compiler's choice
    std::vector<Argument> args;
};

Launch read_launch(const std::string& dir)
{
    std::ifstream in(dir + "/launch.txt");
    if (!in) throw std::runtime_error("cannot read " + dir + "/launch.txt");
    Launch launch;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string key;
        words >> key;
        if (key == "kernel") words >> launch.kernel;
        if (key == "global") words >> launch.global[0] >> launch.global[1];
        if (key == "local") words >> launch.local[0] >> launch.local[1];
        if (key == "options") {
            const std::string cap = "-cl-nv-maxrregcount=";
            for (std::size_t at = line.find(cap); at != std::string::npos; at = line.find(cap, at + 1))
                launch.register_cap = std::atoi(line.c_str() + at + cap.size());  // the last one wins, as in ptxas
        }
        if (key == "arg") {
            Argument arg;
            words >> arg.index >> arg.kind >> arg.bytes >> arg.file;
            arg.data = read_file(dir + "/" + arg.file);
            if (arg.data.size() != arg.bytes) throw std::runtime_error(arg.file + " has the wrong size");
            launch.args.push_back(std::move(arg));
        }
    }
    return launch;
}

}  // namespace

int main(int argc, char** argv)
try {
    if (argc < 2) {
        std::fprintf(stderr, "usage: orb-cuda-replay DIR [--repeat N]\n");
        return 2;
    }
    const std::string dir = argv[1];
    int repeat = 20;
    for (int i = 2; i + 1 < argc; i += 2)
        if (std::strcmp(argv[i], "--repeat") == 0) repeat = std::atoi(argv[i + 1]);

    Launch launch = read_launch(dir);
    std::vector<char> ptx = read_file(dir + "/program.bin");
    ptx.push_back('\0');

    static const Driver driver = open_driver();
    g_driver = &driver;
    check(driver.cuInit(0), "cuInit");
    CUdevice device = 0;
    check(driver.cuDeviceGet(&device, 0), "cuDeviceGet");
    char name[256] = {};
    driver.cuDeviceGetName(name, sizeof name, device);
    CUcontext context = nullptr;
    check(driver.cuCtxCreate(&context, 0, device), "cuCtxCreate");

    std::vector<char> info_log(1 << 16), error_log(1 << 16);
    std::vector<int> options{kJitInfoLog, kJitInfoLogSize, kJitErrorLog, kJitErrorLogSize};
    std::vector<void*> values{info_log.data(), reinterpret_cast<void*>(info_log.size()), error_log.data(),
                              reinterpret_cast<void*>(error_log.size())};
    if (launch.register_cap > 0) {
        options.push_back(kJitMaxRegisters);
        values.push_back(reinterpret_cast<void*>(static_cast<std::uintptr_t>(launch.register_cap)));
    }
    CUmodule module = nullptr;
    const CUresult loaded = driver.cuModuleLoadDataEx(&module, ptx.data(), static_cast<unsigned>(options.size()),
                                                      options.data(), values.data());
    if (loaded != 0) std::fprintf(stderr, "JIT log:\n%s\n", error_log.data());
    check(loaded, "loading the PTX");
    CUfunction function = nullptr;
    check(driver.cuModuleGetFunction(&function, module, launch.kernel.c_str()), "finding the kernel");

    int registers = 0, local_bytes = 0, blocks_per_sm = 0;
    const unsigned group = launch.local[0] * launch.local[1];
    driver.cuFuncGetAttribute(&registers, kAttrRegisters, function);
    driver.cuFuncGetAttribute(&local_bytes, kAttrLocalBytes, function);
    driver.cuOccupancyMaxActiveBlocksPerMultiprocessor(&blocks_per_sm, function, static_cast<int>(group), 0);
    std::printf("device: %s\nkernel: %s, register cap %d: %d registers, %d bytes of local memory per thread, "
                "%d groups of %u per SM\n",
                name, launch.kernel.c_str(), launch.register_cap, registers, local_bytes, blocks_per_sm, group);

    std::vector<void*> params;
    for (Argument& arg : launch.args) {
        if (arg.kind == "value") {
            params.push_back(arg.data.data());
            continue;
        }
        check(driver.cuMemAlloc(&arg.device, arg.bytes), "cuMemAlloc");
        check(driver.cuMemcpyHtoD(arg.device, arg.data.data(), arg.bytes), "cuMemcpyHtoD");
        params.push_back(&arg.device);
    }
    const unsigned grid_x = launch.global[0] / launch.local[0], grid_y = launch.global[1] / launch.local[1];
    const auto run_pass = [&] {
        check(driver.cuLaunchKernel(function, grid_x, grid_y, 1, launch.local[0], launch.local[1], 1, 0, nullptr,
                                    params.data(), nullptr),
              "cuLaunchKernel");
    };

    // One pass from the captured film: it must leave the film OpenCL left,
    // bit for bit (the sums are 64-bit integers, the centre-ray values floats:
    // compared as 4-byte words).
    run_pass();
    check(driver.cuCtxSynchronize(), "the replayed pass");
    std::size_t words = 0, equal = 0;
    for (const Argument& arg : launch.args) {
        if (arg.kind != "film") continue;
        const std::vector<char> expected = read_file(dir + "/arg" + std::to_string(arg.index) + ".after.bin");
        std::vector<char> got(arg.bytes);
        check(driver.cuMemcpyDtoH(got.data(), arg.device, arg.bytes), "cuMemcpyDtoH");
        for (std::size_t at = 0; at + 4 <= arg.bytes; at += 4) {
            ++words;
            if (std::memcmp(got.data() + at, expected.data() + at, 4) == 0) ++equal;
        }
    }
    std::printf("film after one pass: %zu of %zu 4-byte words equal to OpenCL's\n", equal, words);

    orb::device::RenderPassParams pass{};
    for (const Argument& arg : launch.args)
        if (arg.kind == "value" && arg.bytes == sizeof pass) std::memcpy(&pass, arg.data.data(), sizeof pass);
    const double samples = double(pass.settings.width) * pass.settings.height * pass.pass.sample_count;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < repeat; ++i) run_pass();
    check(driver.cuCtxSynchronize(), "the timed passes");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%d passes of %d samples per pixel (%ux%u) in %.4f s: samples_per_second=%.0f\n", repeat,
                pass.pass.sample_count, pass.settings.width, pass.settings.height, seconds,
                samples * repeat / seconds);
    return equal == words ? 0 : 1;
} catch (const std::exception& error) {
    std::fprintf(stderr, "orb-cuda-replay: %s\n", error.what());
    return 1;
}
