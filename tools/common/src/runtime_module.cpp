#include "orb/cli/runtime_module.h"

#include <dlfcn.h>

#include <filesystem>
#include <map>
#include <mutex>

#include "orb/cli/paths.h"

namespace orb::cli {

const RuntimeModule& runtime_module(const std::string& folder, const std::string& file_name,
                                    const std::string& entry_point) {
    static std::mutex mutex;
    static std::map<std::string, RuntimeModule> loaded;  // node-based: references stay valid
    const std::string path = (std::filesystem::path(folder) / file_name).string();
    const std::lock_guard lock(mutex);
    const auto [it, inserted] = loaded.try_emplace(path);
    RuntimeModule& module = it->second;
    if (!inserted) return module;
    module.path = path;
    void* handle = dlopen(module.path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* error = dlerror();
        module.why_not = error ? error : "dlopen failed";
        return module;
    }
    module.entry = dlsym(handle, entry_point.c_str());
    if (!module.entry) module.why_not = module.path + ": no entry point " + entry_point;
    return module;
}

std::string tools_module_folder() {
    const std::filesystem::path bin = std::filesystem::path(executable_path()).parent_path();
    return (bin.parent_path() / "lib" / "orb").string();
}

const RuntimeModule& runtime_module(const std::string& file_name, const std::string& entry_point) {
    return runtime_module(tools_module_folder(), file_name, entry_point);
}

}  // namespace orb::cli
