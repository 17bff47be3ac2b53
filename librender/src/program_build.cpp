#include "program_build.h"

#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace orb::render {
namespace {

namespace fs = std::filesystem;

constexpr std::array<char, 8> kMagic{'O', 'R', 'B', 'C', 'L', 'B', 'I', '1'};

// FNV-1a, 64 bits. Two different offset bases give a 128-bit key, so that an
// accidental collision between two sources is not a practical concern.
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash)
{
    for (unsigned char c : bytes) {
        hash ^= c;
        hash *= 0x100000001b3ULL;
    }
    return hash;
}

std::string hex(std::uint64_t value)
{
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

}  // namespace

std::string program_options_text(const ProgramOptions& options)
{
    std::string text = kKernelLanguageOptions;
    const std::string features = device::kernel_feature_options(options.features);
    if (!features.empty()) text += " " + features;
    if (options.nvidia_max_registers > 0)
        text += " -cl-nv-maxrregcount=" + std::to_string(options.nvidia_max_registers);
    return text;
}

std::string program_cache_key(const cl::Device& device, const std::string& source, const std::string& options)
{
    const cl::Platform platform(device.getInfo<CL_DEVICE_PLATFORM>());
    std::string identity;
    for (const std::string& part :
         {source, options, device.getInfo<CL_DEVICE_NAME>(), device.getInfo<CL_DEVICE_VENDOR>(),
          device.getInfo<CL_DEVICE_VERSION>(), device.getInfo<CL_DRIVER_VERSION>(),
          platform.getInfo<CL_PLATFORM_NAME>(), platform.getInfo<CL_PLATFORM_VERSION>()}) {
        identity += part;
        identity += '\0';
    }
    return hex(fnv1a(identity, 0xcbf29ce484222325ULL)) + hex(fnv1a(identity, 0x84222325cbf29ce4ULL));
}

namespace {

// File layout: magic, 32-char key, payload size (u64), payload FNV-1a (u64), payload.
std::vector<unsigned char> read_cached_binary(const fs::path& path, const std::string& key)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    std::array<char, 8> magic{};
    std::string stored_key(key.size(), '\0');
    std::uint64_t size = 0, checksum = 0;
    in.read(magic.data(), magic.size());
    in.read(stored_key.data(), static_cast<std::streamsize>(stored_key.size()));
    in.read(reinterpret_cast<char*>(&size), sizeof size);
    in.read(reinterpret_cast<char*>(&checksum), sizeof checksum);
    if (!in || magic != kMagic || stored_key != key || size == 0 || size > (std::uint64_t{1} << 31)) return {};
    std::vector<unsigned char> payload(size);
    in.read(reinterpret_cast<char*>(payload.data()), static_cast<std::streamsize>(size));
    if (!in || in.peek() != std::char_traits<char>::eof()) return {};
    const std::string_view bytes(reinterpret_cast<const char*>(payload.data()), payload.size());
    if (fnv1a(bytes, 0xcbf29ce484222325ULL) != checksum) return {};
    return payload;
}

// Writes to a unique temporary name beside the target and renames it into
// place, so readers see either no file or a whole one. Failures are ignored:
// the cache only saves time.
void write_cached_binary(const fs::path& path, const std::string& key, const std::vector<unsigned char>& payload)
{
    try {
        std::error_code ec;
        fs::create_directories(path.parent_path(), ec);
        std::random_device entropy;
        const fs::path temporary =
            path.string() + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(entropy());
        {
            std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
            if (!out) return;
            const std::uint64_t size = payload.size();
            const std::uint64_t checksum = fnv1a(
                std::string_view(reinterpret_cast<const char*>(payload.data()), payload.size()), 0xcbf29ce484222325ULL);
            out.write(kMagic.data(), kMagic.size());
            out.write(key.data(), static_cast<std::streamsize>(key.size()));
            out.write(reinterpret_cast<const char*>(&size), sizeof size);
            out.write(reinterpret_cast<const char*>(&checksum), sizeof checksum);
            out.write(reinterpret_cast<const char*>(payload.data()), static_cast<std::streamsize>(payload.size()));
            out.close();
            if (!out) {
                fs::remove(temporary, ec);
                return;
            }
        }
        fs::rename(temporary, path, ec);
        if (ec) fs::remove(temporary, ec);
    } catch (...) {
        // Ignored on purpose (see above).
    }
}

std::string build_log(const cl::Program& program, const cl::Device& device)
{
    try {
        return program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device);
    } catch (const cl::Error&) {
        return "(the driver gave no build log)";
    }
}

std::vector<unsigned char> program_binary(const cl::Program& program)
{
    try {
        std::vector<std::vector<unsigned char>> binaries = program.getInfo<CL_PROGRAM_BINARIES>();
        if (binaries.size() == 1) return std::move(binaries.front());
    } catch (const cl::Error&) {
    }
    return {};
}

std::optional<cl::Program> try_load_binary(const cl::Context& context, const cl::Device& device,
                                           const std::vector<unsigned char>& binary, const std::string& options)
{
    try {
        cl_int status = CL_SUCCESS;
        std::vector<cl_int> binary_status;
        cl::Program program(context, {device}, cl::Program::Binaries{binary}, &binary_status, &status);
        if (status != CL_SUCCESS || binary_status.empty() || binary_status.front() != CL_SUCCESS) return std::nullopt;
        program.build({device}, options.c_str());
        return program;
    } catch (const cl::Error&) {
        return std::nullopt;  // stale or corrupt: rebuild from source
    }
}

}  // namespace

std::string binary_cache_dir()
{
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    if (xdg && *xdg == '/') return std::string(xdg) + "/orb";
    const char* home = std::getenv("HOME");
    if (home && *home) return std::string(home) + "/.cache/orb";
    return {};
}

ProgramBuild build_program(const cl::Context& context, const cl::Device& device, const std::string& source,
                           const std::string& options, bool use_cache, bool show_build_log,
                           const std::function<void()>& on_slow_build)
{
    const std::string cache_dir = use_cache ? binary_cache_dir() : std::string();
    fs::path cache_file;
    std::string key;
    if (!cache_dir.empty()) {
        key = program_cache_key(device, source, options);
        cache_file = fs::path(cache_dir) / (key + ".bin");
        const std::vector<unsigned char> binary = read_cached_binary(cache_file, key);
        if (!binary.empty())
            if (std::optional<cl::Program> program = try_load_binary(context, device, binary, options))
                return {*program, true, nullptr};
    }

    cl::Program program(context, source);
    auto building = std::make_unique<SlowBuildNotice>(on_slow_build, std::chrono::seconds(1));
    try {
        program.build({device}, options.c_str());
    } catch (const cl::Error& error) {
        const std::string device_name = device.getInfo<CL_DEVICE_NAME>();
        throw std::runtime_error("the OpenCL kernels failed to build on " + device_name + " (" +
                                 describe_cl_error(error) + "); build log:\n" + build_log(program, device));
    }
    if (show_build_log)  // compiler remarks, register counts
        std::fprintf(stderr, "%s\n", build_log(program, device).c_str());
    if (!cache_file.empty()) {
        const std::vector<unsigned char> binary = program_binary(program);
        if (!binary.empty()) write_cached_binary(cache_file, key, binary);
    }
    return {program, false, std::move(building)};
}

}  // namespace orb::render
