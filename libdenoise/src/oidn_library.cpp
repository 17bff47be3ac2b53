#include "orb/denoise/oidn_library.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "oidn_api.h"

#ifndef ORB_OIDN_PREFIX
#error "ORB_OIDN_PREFIX must name where scripts/install-deps.sh installs OIDN (libdenoise/CMakeLists.txt)"
#endif

namespace orb::denoise {
namespace {

struct Loaded {
    oidn::Api api{};
    std::string path;
    std::string failure;  // empty when loaded
};

std::string environment_library() {
    const char* value = std::getenv(kLibraryVariable);
    return value ? value : "";
}

// A folder names the library inside it, so ORB_OIDN_LIBRARY may be either.
std::string library_in(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return (std::filesystem::path(path) / kLibraryName).string();
    return path;
}

const char* how_to_install() {
    return "install it with scripts/install-deps.sh (Intel's build from PyPI's pyoidn 2.5.1), or point " 
           "ORB_OIDN_LIBRARY at a libOpenImageDenoise.so.2 of OIDN 2 (docs/orb-denoise.md)";
}

template <typename Function>
bool bind(void* handle, const char* name, Function& slot, std::string& missing) {
    slot = reinterpret_cast<Function>(dlsym(handle, name));
    if (!slot) missing += std::string(missing.empty() ? "" : ", ") + name;
    return slot != nullptr;
}

bool bind_all(void* handle, oidn::Api& api, std::string& missing) {
    bool ok = true;
#define ORB_BIND(name) ok = bind(handle, #name, api.name, missing) && ok
    ORB_BIND(oidnNewDevice);
    ORB_BIND(oidnSetDeviceInt);
    ORB_BIND(oidnGetDeviceInt);
    ORB_BIND(oidnCommitDevice);
    ORB_BIND(oidnGetDeviceError);
    ORB_BIND(oidnReleaseDevice);
    ORB_BIND(oidnNewBuffer);
    ORB_BIND(oidnWriteBuffer);
    ORB_BIND(oidnReadBuffer);
    ORB_BIND(oidnReleaseBuffer);
    ORB_BIND(oidnNewBufferWithStorage);
    ORB_BIND(oidnGetBufferData);
    ORB_BIND(oidnWriteBufferAsync);
    ORB_BIND(oidnReadBufferAsync);
    ORB_BIND(oidnSyncDevice);
    ORB_BIND(oidnNewFilter);
    ORB_BIND(oidnSetFilterImage);
    ORB_BIND(oidnSetFilterBool);
    ORB_BIND(oidnSetFilterInt);
    ORB_BIND(oidnCommitFilter);
    ORB_BIND(oidnExecuteFilter);
    ORB_BIND(oidnExecuteFilterAsync);
    ORB_BIND(oidnReleaseFilter);
#undef ORB_BIND
    return ok;
}

// Tries each candidate in turn; the first that opens must have every entry
// point (a library of the wrong major version is an error, not skipped).
Loaded load() {
    Loaded loaded;
    std::string tried;
    const bool from_environment = !environment_library().empty();
    for (const std::string& candidate : library_candidates()) {
        // RTLD_LOCAL: OIDN's symbols (and its TBB) stay out of the global namespace.
        void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = dlerror();
            tried += std::string(tried.empty() ? "" : "; ") + (why ? why : candidate + ": cannot be loaded");
            continue;
        }
        std::string missing;
        if (!bind_all(handle, loaded.api, missing)) {
            loaded.failure = candidate + " is not Intel Open Image Denoise 2 (no " + missing + "); " + how_to_install();
            return loaded;
        }
        loaded.path = candidate;
        return loaded;
    }
    loaded.failure = std::string("Intel Open Image Denoise (OIDN 2) did not load") +
                     (from_environment ? std::string(" from ") + kLibraryVariable : std::string()) + " (" + tried +
                     "); " + how_to_install();
    return loaded;
}

const Loaded& loaded() {
    static Loaded result;
    static std::once_flag once;
    std::call_once(once, [] { result = load(); });
    return result;
}

}  // namespace

std::string installed_library_path() {
    return (std::filesystem::path(ORB_OIDN_PREFIX) / "pyoidn" / "oidn" / "lib" / kLibraryName).string();
}

std::vector<std::string> library_candidates() {
    const std::string from_environment = environment_library();
    if (!from_environment.empty()) return {library_in(from_environment)};
    return {installed_library_path(), kLibraryName};
}

const oidn::Api& load_oidn() {
    const Loaded& l = loaded();
    if (!l.failure.empty()) throw DenoiserUnavailable(l.failure);
    return l.api;
}

const std::string& loaded_library_path() { return loaded().path; }

}  // namespace orb::denoise
